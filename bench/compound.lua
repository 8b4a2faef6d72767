-- Compound shapes (lists of convex parts) measured three ways, from the repository root:
--   luajit bench/compound.lua timing 100000    time per call against the convex pair calls needed
--   lua5.4 bench/compound.lua excess 11 1000   how much longer the push is than the true least
--                                              translation (seed, number of scenes)
--   lua5.4 bench/compound.lua only pushFloor 3000
--                                              one timing row alone (its key, calls), for an
--                                              instruction count that load cannot disturb:
--                                              valgrind --tool=callgrind at 10000 and 30000
--                                              calls, the difference over 20000 is the cost per
--                                              call (LuaJIT: its trace penalties are random,
--                                              seeded by getrandom, so the traces and the count
--                                              differ from run to run; compare medians over
--                                              several runs, or fix the seed)
--                                              (row scanFloor: the list's checks and box tests
--                                              alone, the crate far above the floor)
--   lua5.4 bench/compound.lua count pushFloor 300
--                                              one timing row's VM instructions per call, by
--                                              function (a debug.sethook count hook)
--   luajit bench/compound.lua ratio pushFloor pushPairs 100000
--                                              one row's time over another's, the median (and
--                                              2nd and 6th) of 7 rounds timing them back to back
--                                              in one process: steadier than separate rows when
--                                              the machine is shared
--   luajit bench/compound.lua draws 16 100000
--                                              the target rows' ratios (pushFloor / pushPairs,
--                                              booleanFloor / booleanPairs, pushTurned /
--                                              pushTurnedPairs), each by `ratio` in 16 processes
--                                              of this interpreter (LuaJIT draws its traces anew
--                                              in each): the median of the processes' medians
--                                              and their range, as a Markdown table (make bench)
-- The excess mode compares with spec/support/union.lua, which shares no code with polygon.lua.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local parts = require "parts"

local V, B = polygon.polygonsCollideV, polygon.polygonsCollide

-- Timing: a crate 8 x 8 sunk 3 into a floor of 20 parts, at 100 positions along it, against the
-- convex calls on exactly the parts whose boxes overlap the crate (the least a compound call
-- could cost) and against a naive loop that computes each part's box first, as a game would.
-- The rows in order: key, name, body (call number -> a number for the checksum).
local function timingRows()
  local floor = parts.floor(20, 10, 100, 0)
  local crates = {}
  for k = 0, 99 do crates[#crates + 1] = parts.box(k * 1.91, 95, 8, 8) end
  local above = {}   -- the crate far above the floor: the list's checks and box tests alone
  for k = 0, 99 do above[#above + 1] = parts.box(k * 1.91, 50, 8, 8) end
  local corner = { parts.box(0, 0, 10, 100), parts.box(10, 90, 100, 10) }
  local cornerCrates = {}
  for k = 0, 99 do cornerCrates[#cornerCrates + 1] = parts.box(5 + k * 0.03, 85, 8, 8) end

  -- shapes that are not axis-parallel rectangles, for the general faces: the crate turned by
  -- 0.5 radian against the floor, and the crate against a floor of 20 columns with sloped tops
  local turned = {}
  for k = 0, 99 do
    local cx, cy, c, s = 4 + k * 1.91, 98, math.cos(0.5), math.sin(0.5)
    local p = {}
    for _, v in ipairs({ { -4, -4 }, { 4, -4 }, { 4, 4 }, { -4, 4 } }) do
      p[#p + 1] = cx + c * v[1] - s * v[2]
      p[#p + 1] = cy + s * v[1] + c * v[2]
    end
    turned[k + 1] = p
  end
  local slope = {}
  for k = 0, 19 do
    local y1, y2 = 100 + (k % 3) * 2, 100 + ((k + 1) % 3) * 2
    slope[k + 1] = { k * 10, y1, k * 10 + 10, y2, k * 10 + 10, y1 + 30, k * 10, y1 + 30 }
  end

  local needed = {}   -- for each crate, the floor parts whose boxes overlap its box
  for k, c in ipairs(crates) do
    local list = {}
    for _, p in ipairs(floor) do
      if p[1] < c[3] and c[1] < p[3] then list[#list + 1] = p end
    end
    needed[k] = list
  end
  local neededTurned = {}   -- the same for the turned crates
  for k, c in ipairs(turned) do
    local x0, y0, x1, y1 = polygon.polygonBounds(c)
    local list = {}
    for _, p in ipairs(floor) do
      local px0, py0, px1, py1 = polygon.polygonBounds(p)
      if px0 < x1 and x0 < px1 and py0 < y1 and y0 < py1 then list[#list + 1] = p end
    end
    neededTurned[k] = list
  end

  return {
    { "pushFloor", "compound V: crate vs 20-part floor", function(i)
      return (V(floor, crates[i % 100 + 1]))
    end },
    { "pushPairs", "sum of convex V pair calls it needs", function(i)
      local c, sum = crates[i % 100 + 1], 0
      for _, p in ipairs(needed[i % 100 + 1]) do sum = sum + (V(p, c) or 0) end
      return sum
    end },
    { "pushNaive", "naive loop: per part box, then V pair call", function(i)
      local c, sum = crates[i % 100 + 1], 0
      local cx0, cy0, cx1, cy1 = c[1], c[2], c[5], c[6]
      for _, p in ipairs(floor) do
        local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
        for j = 1, #p, 2 do
          local x, y = p[j], p[j + 1]
          if x < x0 then x0 = x end
          if x > x1 then x1 = x end
          if y < y0 then y0 = y end
          if y > y1 then y1 = y end
        end
        if x0 < cx1 and cx0 < x1 and y0 < cy1 and cy0 < y1 then sum = sum + (V(p, c) or 0) end
      end
      return sum
    end },
    { "scanFloor", "compound V: crate far above the floor (no pair)", function(i)
      return (V(floor, above[i % 100 + 1])) and 1 or 0
    end },
    { "booleanFloor", "compound boolean: crate vs 20-part floor", function(i)
      return B(floor, crates[i % 100 + 1]) and 1 or 0
    end },
    { "booleanPairs", "sum of convex boolean pair calls", function(i)
      local c, sum = crates[i % 100 + 1], 0
      for _, p in ipairs(needed[i % 100 + 1]) do sum = sum + (B(p, c) and 1 or 0) end
      return sum
    end },
    { "pushCorner", "compound V: crate in a concave corner", function(i)
      return (V(corner, cornerCrates[i % 100 + 1]))
    end },
    { "pushTurned", "compound V: turned crate vs 20-part floor", function(i)
      return (V(floor, turned[i % 100 + 1]))
    end },
    { "pushTurnedPairs", "sum of convex V pair calls it needs (turned)", function(i)
      local c, sum = turned[i % 100 + 1], 0
      for _, p in ipairs(neededTurned[i % 100 + 1]) do sum = sum + (V(p, c) or 0) end
      return sum
    end },
    { "pushSlope", "compound V: crate vs 20 sloped columns", function(i)
      return (V(slope, crates[i % 100 + 1]))
    end },
    { "circleFloor", "compound circle V: circle vs 20-part floor", function(i)
      return (polygon.polygonCircleCollideV(floor, 5 + (i % 100) * 1.9, 97, 5))
    end },
    { "circlePart", "convex circle V: circle vs one part", function(i)
      local x = 5 + (i % 100) * 1.9
      return (polygon.polygonCircleCollideV(floor[math.floor(x / 10) + 1], x, 97, 5))
    end },
  }
end

local function runRow(body, count)
  local checksum = 0
  for i = 1, count do checksum = checksum + (body(i) or 0) end
  return checksum
end

local function timing(count)
  local rows = timingRows()
  for round = 1, 2 do
    print("round", round)
    for _, row in ipairs(rows) do
      local body = row[3]
      body(1)
      local t0 = os.clock()
      local checksum = runRow(body, count)
      local seconds = os.clock() - t0
      print(("%-44s %8.2f us/call  (checksum %.6g)"):format(row[2], seconds / count * 1e6, checksum))
    end
  end
end

-- One row alone, `count` calls, its checksum printed.
local function only(key, count)
  for _, row in ipairs(timingRows()) do
    if row[1] == key then
      print(key, count, ("checksum %.6g"):format(runRow(row[3], count)))
      return
    end
  end
  io.stderr:write("no row " .. tostring(key) .. "\n")
  os.exit(2)
end

-- One row's VM instructions per call, in all and by the function that ran them (the line it
-- is defined at), the 20 largest.
local function count(key, calls)
  local body
  for _, row in ipairs(timingRows()) do
    if row[1] == key then body = row[3] end
  end
  if not body then
    io.stderr:write("no row " .. tostring(key) .. "\n")
    os.exit(2)
  end
  body(1)   -- the first call prepares the lists
  local byFunction, total = {}, 0
  local getinfo = debug.getinfo
  debug.sethook(function()
    local info = getinfo(2, "S")
    local where = info.short_src .. ":" .. info.linedefined
    byFunction[where] = (byFunction[where] or 0) + 1
    total = total + 1
  end, "", 1)
  runRow(body, calls)
  debug.sethook()
  local places = {}
  for where in pairs(byFunction) do places[#places + 1] = where end
  table.sort(places, function(a, b) return byFunction[a] > byFunction[b] end)
  print(("%s: %.0f VM instructions per call"):format(key, total / calls))
  for i = 1, math.min(#places, 20) do
    print(("%9.1f  %s"):format(byFunction[places[i]] / calls, places[i]))
  end
end

-- The median, 2nd and 6th of 7 ratios of row key's time to row base's, each round timing both
-- back to back (`calls` calls each), and row key's median time per call.
local function ratio(key, base, calls)
  local bodies = {}
  for _, row in ipairs(timingRows()) do bodies[row[1]] = row[3] end
  if not (bodies[key] and bodies[base]) then
    io.stderr:write("no row " .. tostring(bodies[key] and base or key) .. "\n")
    os.exit(2)
  end
  local function seconds(body)
    local t0 = os.clock()
    runRow(body, calls)
    return os.clock() - t0
  end
  seconds(bodies[key]); seconds(bodies[base])   -- warm up (and prepare the lists)
  local ratios, times = {}, {}
  for round = 1, 7 do
    local t = seconds(bodies[key])
    ratios[round], times[round] = t / seconds(bodies[base]), t / calls * 1e6
  end
  table.sort(ratios); table.sort(times)
  print(("%s / %s: %.2f (%.2f-%.2f), %s %.2f us per call"):format(key, base, ratios[4], ratios[2],
    ratios[6], key, times[4]))
end

-- Excess: random clusters of 1-5 convex parts against 1-2, terrains of 12 columns with a crate,
-- terrains against clusters, both argument orders, at offsets 0, 1e5, 1e9 and 1e12 + 0.375.
local function excess(seed, trials)
  local union, scenes, prng = require "union", require "scenes", require "prng"
  local g = prng.new(seed)
  local offsets = { 0, 1e5, 1e9, 1e12 + 0.375 }
  local total = { collisions = 0, overSlack = 0, shorter = 0, notSeparated = 0, worst = 0 }
  local byOffset = {}
  for _, off in ipairs(offsets) do
    byOffset[off] = { collisions = 0, overSlack = 0, longer = 0, worst = 0 }
  end

  local function measure(s1, s2, off)
    local overlap, dx, dy = V(s1, s2)
    assert(parts.collide(s1, s2) == (overlap ~= false), "the boolean answer differs from the oracle's")
    if not overlap then return end
    local least = union.leastTranslation(s1, s2)
    local over = overlap - least
    local slack = parts.slack(s1, s2)   -- three times the face margin
    local row = byOffset[off]
    total.collisions, row.collisions = total.collisions + 1, row.collisions + 1
    if parts.collide(s1, parts.translate(s2, dx, dy)) then total.notSeparated = total.notSeparated + 1 end
    if over < -1e-9 * (1 + least) then total.shorter = total.shorter + 1 end
    if over > slack then total.overSlack, row.overSlack = total.overSlack + 1, row.overSlack + 1 end
    if over > 1e-12 * (1 + least) then row.longer = row.longer + 1 end
    total.worst, row.worst = math.max(total.worst, over), math.max(row.worst, over)
  end

  for _ = 1, trials do
    local kind = g:int(1, 3)
    local off = offsets[g:int(1, 4)]
    local s1, s2 = scenes.pair(g, kind)
    s1, s2 = parts.translate(s1, off, off), parts.translate(s2, off, off)
    measure(s1, s2, off)
    measure(s2, s1, off)
  end

  print(("collisions %d  beyond 3x the face margin %d  shorter than the oracle %d  not separated %d"
    .. "  largest excess %.3g"):format(total.collisions, total.overSlack, total.shorter,
    total.notSeparated, total.worst))
  for _, off in ipairs(offsets) do
    local row = byOffset[off]
    print(("offset %-8.3g collisions %4d  longer than the least translation by > 1e-12 (1 + d): %4d"
      .. "  beyond 3x the face margin: %3d  largest excess %.3g"):format(off, row.collisions, row.longer,
      row.overSlack, row.worst))
  end
end

-- The target rows, each pair's ratio in `processes` processes of this interpreter (arg[-1]),
-- `calls` calls a round.
local TARGET_ROWS = {
  { "pushFloor", "pushPairs", "`polygonsCollideV`, crate against the 20-part floor" },
  { "booleanFloor", "booleanPairs", "`polygonsCollide`, crate against the 20-part floor" },
  { "pushTurned", "pushTurnedPairs", "`polygonsCollideV`, the crate turned 0.5 radian (no target)" },
}

local function draws(processes, calls)
  local interpreter = arg[-1] or "lua"
  local ratios = {}
  for p = 1, processes do
    for r, row in ipairs(TARGET_ROWS) do
      local command = ("%s bench/compound.lua ratio %s %s %d"):format(interpreter, row[1], row[2], calls)
      local child = assert(io.popen(command))
      local line = child:read("*a")
      child:close()
      local value = tonumber(line:match(": ([%d.]+) %("))
      if not value then
        io.stderr:write("compound.lua draws: no ratio from `" .. command .. "`: " .. line .. "\n")
        os.exit(1)
      end
      ratios[r] = ratios[r] or {}
      ratios[r][p] = value
    end
  end
  print(("| %s, ratio to the pair calls it needs | median of %d processes | their range |"):format(
    interpreter, processes))
  print("|---|---:|---:|")
  for r, row in ipairs(TARGET_ROWS) do
    local list = ratios[r]
    table.sort(list)
    local n = #list
    local median = n % 2 == 1 and list[(n + 1) / 2] or (list[n / 2] + list[n / 2 + 1]) / 2
    print(("| %s | %.2f | %.2f-%.2f |"):format(row[3], median, list[1], list[n]))
  end
end

local mode = arg[1]
if mode == "timing" then
  timing(tonumber(arg[2]) or 20000)
elseif mode == "excess" then
  excess(tonumber(arg[2]) or 11, tonumber(arg[3]) or 300)
elseif mode == "only" then
  only(arg[2], tonumber(arg[3]) or 1000)
elseif mode == "count" then
  count(arg[2], tonumber(arg[3]) or 300)
elseif mode == "ratio" then
  ratio(arg[2], arg[3] or "pushPairs", tonumber(arg[4]) or 100000)
elseif mode == "draws" then
  draws(tonumber(arg[2]) or 16, tonumber(arg[3]) or 100000)
else
  io.stderr:write("usage: lua bench/compound.lua timing [calls] | excess [seed] [scenes]"
    .. " | only key [calls] | count key [calls] | ratio key [base] [calls]"
    .. " | draws [processes] [calls]\n")
  os.exit(2)
end
