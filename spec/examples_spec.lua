-- examples/scene.lua runs with the interpreter running these specs (plain Lua, no LÖVE), exits
-- with status 0 and prints the measures, point queries and collisions checked below by hand.
local EXIT_MARK = "@@exit status: "

local interpreter = require "interpreter"

-- runs examples/scene.lua from the repository root; returns its output lines and exit status
local function runScene()
  local lua = assert(interpreter())
  local pipe = assert(io.popen(lua .. " examples/scene.lua 2>&1; echo \"" .. EXIT_MARK .. "$?\""))
  local out = pipe:read("*a")
  pipe:close()
  local lines, status = {}, nil
  for line in out:gmatch("[^\n]*") do
    local s = line:match("^" .. EXIT_MARK:gsub("%p", "%%%0") .. "(%d+)$")
    if s then status = tonumber(s) elseif line ~= "" then lines[#lines + 1] = line end
  end
  return lines, status, out
end

-- the first line matching the Lua pattern, or nil
local function findLine(lines, pattern)
  for _, line in ipairs(lines) do
    if line:find(pattern) then return line end
  end
end

describe("examples/scene.lua", function()
  local lines, status, out

  setup(function()
    lines, status, out = runScene()
  end)

  it("exits with status 0", function()
    assert.are.equal(0, status, out)
  end)

  it("prints no NaN, no infinity and no Lua error", function()
    local lower = " " .. out:lower() .. " "
    assert.is_nil(lower:find("[^%a]nan[^%a]"), out)
    assert.is_nil(lower:find("[^%a]inf[^%a]"), out)
    assert.is_nil(out:find("stack traceback", 1, true), out)
  end)

  it("prints the crate: a 60 by 60 square at 100..160, cw, area 3600, convex, centre (130, 130)", function()
    assert.is_truthy(findLine(lines,
      "^%s*crate%s+winding cw%s+area%s+3600%.00%s+convex%s+centre %(130%.00, 130%.00%)$"), out)
  end)

  it("prints the wedge: right triangle with legs 70 and 50, area 70*50/2 = 1750", function()
    -- centre ((150 + 220 + 150)/3, (150 + 150 + 200)/3) = (173.33, 166.67)
    assert.is_truthy(findLine(lines,
      "^%s*wedge%s+winding cw%s+area%s+1750%.00%s+convex%s+centre %(173%.33, 166%.67%)$"), out)
  end)

  it("prints the arrow as concave with area 560", function()
    -- triangle (250,10),(290,30),(250,50): 40*40/2 = 800, minus the notch to (262,30):
    -- 40*12/2 = 240; 800 - 240 = 560; centre (1052/4, 120/4) = (263, 30)
    assert.is_truthy(findLine(lines,
      "^%s*arrow%s+winding cw%s+area%s+560%.00%s+concave%s+centre %(263%.00, 30%.00%)$"), out)
  end)

  it("puts (160, 130) on the crate's right edge inside it and (100, 130) on its left edge outside", function()
    assert.is_truthy(findLine(lines, "^%s*%(160, 130%) is in: crate$"), out)
    assert.is_truthy(findLine(lines, "^%s*%(100, 130%) is in: nothing$"), out)
  end)

  it("puts the arrow's reflex vertex (262, 30) outside and (270, 30) inside", function()
    assert.is_truthy(findLine(lines, "^%s*%(262, 30%) is in: nothing$"), out)
    assert.is_truthy(findLine(lines, "^%s*%(270, 30%) is in: arrow$"), out)
  end)

  it("reports crate and wedge overlapping by 10", function()
    -- x: crate [100,160], wedge [150,220]: min(160 - 150, 220 - 100) = 10; y: the same 10;
    -- the wedge's hypotenuse axis gives 1200/sqrt(7400) = 13.95
    assert.is_truthy(findLine(lines, "^%s*crate and wedge overlap by 10%.00: move wedge by "), out)
  end)

  it("reports floor and boulder overlapping by 10 with the boulder moved up by (0, -10)", function()
    -- y: floor [240,260], boulder [200,250]: min(260 - 200, 250 - 240) = 10, push -y;
    -- the boulder's own edge axes give 26.7 and more
    assert.is_truthy(findLine(lines,
      "^%s*floor and boulder overlap by 10%.00: move boulder by %(0%.00, %-10%.00%)$"), out)
  end)

  it("reports the ball colliding with the hexagon", function()
    assert.is_truthy(findLine(lines, "^%s*hexagon and ball overlap by "), out)
  end)

  it("ends with no colliding pairs left after resolving", function()
    assert.is_truthy(findLine(lines, "^after resolving"), out)
    assert.are.equal("no colliding pairs left", lines[#lines], out)
  end)
end)
