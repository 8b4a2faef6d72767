-- luacheck: globals love
-- love.math.triangulate on the outlines bench/concave.lua exports (cases.lua beside this file,
-- copied there as main.lua): per case one line "name ok|fail microseconds-per-vertex triangles
-- relative-area-error", then quits. Areas of the result are summed in doubles.
local function area(p)
  local s = 0
  for i = 1, #p, 2 do
    local j = i + 2 > #p and 1 or i + 2
    s = s + (p[i] - p[1]) * (p[j + 1] - p[2]) - (p[j] - p[1]) * (p[i + 1] - p[2])
  end
  return math.abs(s) / 2
end

function love.load()
  for _, case in ipairs(require("cases")) do
    local name, points = case[1], case[2]
    -- a warm-up, then the best of three rounds, as bench/concave.lua does (one run when slow)
    local best, ok, tris = math.huge, nil, nil
    for round = 0, 3 do
      local runs, start = 0, love.timer.getTime()
      repeat
        ok, tris = pcall(love.math.triangulate, points)
        runs = runs + 1
      until not ok or love.timer.getTime() - start > (round == 0 and 0.1 or 0.2) or runs >= 1000
      local perVertex = (love.timer.getTime() - start) / runs / (#points / 2) * 1e6
      local slow = perVertex * #points > 2e5   -- over 0.1 s a run: that one run will do
      if round > 0 or slow then best = math.min(best, perVertex) end
      if not ok or slow then break end
    end
    local perVertex = best
    if ok then
      local sum = 0
      for _, t in ipairs(tris) do sum = sum + area(t) end
      local a = area(points)
      print(name, "ok", perVertex, #tris, math.abs(sum - a) / a)
    else
      print(name, "fail", perVertex, 0, -1)
    end
    io.stdout:flush()
  end
  love.event.quit()
end
