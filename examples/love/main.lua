-- The polygon tutorial's five interactive figures, a sixth for concave shapes and a seventh for
-- rays, run against the real polygon.lua in LÖVE 11.
--
--   love examples/love                        from the repository root: keys 1-7 switch scenes
--   love examples/love --screenshots DIR      headless: play a scripted drag in every scene, write
--                                             DIR/scene1.png ... DIR/scene7.png, exit with status 0
--
-- Every value drawn comes from polygon.lua; this file and the scenes only draw and drag.

-- luacheck: read globals arg
local commandLine = arg or {}

local screenshotDir
for i = 1, #commandLine do
  if commandLine[i] == "--screenshots" then
    screenshotDir = commandLine[i + 1] or ""
  end
end

if screenshotDir then
  -- Nobody is there to read LÖVE's error screen: report and fail, so CI sees a non-zero status.
  love.errorhandler = function(message)
    io.stderr:write(debug.traceback("polygon.lua demos: " .. tostring(message), 2), "\n")
    io.stderr:flush()
    os.exit(1)
  end
end

-- Finding polygon.lua. LÖVE's own loader looks in this folder first (a copy of polygon.lua here
-- wins). Then POLYGON_PATH (a directory holding polygon.lua), then the repository root two levels up
-- from this folder, then LUA_PATH / the default package.path.
local function prependPath(directory)
  package.path = directory .. "/?.lua;" .. package.path
end
prependPath(love.filesystem.getSource() .. "/../..")
local override = os.getenv("POLYGON_PATH")
if override and override ~= "" then
  prependPath(override)
end

local polygon = require "polygon"
local ui = require "ui"

local SCENES = {
  "scenes.convex", "scenes.contains", "scenes.collision", "scenes.resolution", "scenes.circle",
  "scenes.concave", "scenes.rays",
}
local scenes = {}
for i, name in ipairs(SCENES) do
  scenes[i] = require(name)(polygon, ui)
end
local current = 1

-- ".../examples/love/../../polygon.lua" reads better as ".../polygon.lua"
local function withoutDotDot(path)
  local shorter
  repeat
    path, shorter = path:gsub("/[^/]+/%.%./", "/", 1)
  until shorter == 0
  return path
end

-- Where polygon.lua came from, relative to the repository when it is the repository's own (the
-- footer of the committed screenshots must not carry the machine's directories).
local function whereIsPolygon()
  if love.filesystem.getInfo("polygon.lua") then
    return "polygon.lua from the game folder"
  end
  local path = package.searchpath and package.searchpath("polygon", package.path)
  if not path then
    return "polygon from package.loaders"
  end
  path = withoutDotDot(path)
  local root = withoutDotDot(love.filesystem.getSource() .. "/../../")
  if path:sub(1, #root) == root then
    return "polygon.lua from the repository: " .. path:sub(#root + 1)
  end
  return "polygon.lua from " .. path
end
local origin = whereIsPolygon()

local function drawFrame()
  local colors = ui.colors
  love.graphics.clear(colors.background)
  love.graphics.setLineJoin("miter")
  scenes[current].draw()

  love.graphics.setFont(ui.font("small"))
  local x = 24
  for i, scene in ipairs(scenes) do
    local text = ("%d  %s"):format(i, scene.title)
    local width = ui.font("small"):getWidth(text)
    if i == current then
      ui.setColor(colors.blue, 0.8)
      love.graphics.rectangle("fill", x - 6, 6, width + 12, 22, 4, 4)
      ui.setColor(colors.text)
    else
      ui.setColor(colors.dim)
    end
    love.graphics.print(text, x, 8)
    x = x + width + 22
  end

  ui.label(scenes[current].help, 24, ui.HEIGHT - 46, colors.text, "small")
  ui.label("Keys 1-7: scene    R: reset    Esc: quit    " .. origin, 24, ui.HEIGHT - 26, colors.dim, "small")
end

-- Screenshots ------------------------------------------------------------------------------------

local MOVE_STEPS = 12 -- a scripted move is played as this many mouse moves, as a hand would drag

local function playScript(index)
  local scene = scenes[index]
  local x, y = 0, 0
  for _, step in ipairs(scene.script) do
    local action = step[1]
    if action == "press" then
      x, y = step[2], step[3]
      scene.pressed(x, y, 1)
      assert(scene.grab, ("scene %d: the scripted press at (%d, %d) grabbed nothing"):format(index, x, y))
    elseif action == "move" then
      local fromX, fromY = x, y
      for k = 1, MOVE_STEPS do
        local nx = fromX + (step[2] - fromX) * k / MOVE_STEPS
        local ny = fromY + (step[3] - fromY) * k / MOVE_STEPS
        scene.moved(nx, ny, nx - x, ny - y)
        x, y = nx, ny
      end
    elseif action == "release" then
      scene.released(x, y, 1)
    else
      error(("scene %d: unknown script step %s"):format(index, tostring(action)))
    end
  end
  for _ = 1, scene.scriptFrames or 0 do
    scene.update()
  end
  if scene.check then
    scene.check()
  end
end

-- Fails unless the picture shows something: several colours, and not all background.
local function checkNotBlank(image, index)
  local counts, distinct, most = {}, 0, 0
  local width, height = image:getDimensions()
  for py = 0, height - 1 do
    for px = 0, width - 1 do
      local r, g, b = image:getPixel(px, py)
      local key = math.floor(r * 255 + 0.5) * 65536 + math.floor(g * 255 + 0.5) * 256
        + math.floor(b * 255 + 0.5)
      local count = (counts[key] or 0) + 1
      if count == 1 then
        distinct = distinct + 1
      end
      counts[key] = count
      most = math.max(most, count)
    end
  end
  local drawn = 1 - most / (width * height)
  if distinct < 8 or drawn < 0.05 then
    error(("scene %d: the picture looks blank (%d colours, %.1f%% off the background)")
      :format(index, distinct, drawn * 100))
  end
  return distinct, drawn
end

local function writeScreenshot(index)
  local canvas = love.graphics.newCanvas(ui.WIDTH, ui.HEIGHT)
  love.graphics.push("all")
  love.graphics.setCanvas({ canvas, stencil = true })
  drawFrame()
  love.graphics.pop()
  local image = canvas:newImageData()
  local distinct, drawn = checkNotBlank(image, index)
  local path = ("%s/scene%d.png"):format(screenshotDir, index)
  local file = assert(io.open(path, "wb"))
  local bytes = image:encode("png"):getString()
  assert(file:write(bytes))
  assert(file:close())
  print(("scene %d: wrote %s (%d bytes, %d colours, %.0f%% drawn)"):format(index, path, #bytes, distinct,
    drawn * 100))
end

-- LÖVE callbacks ---------------------------------------------------------------------------------

function love.load()
  if screenshotDir == "" then
    error("usage: love examples/love --screenshots DIR")
  end
  ui.load()
  print(origin)
end

local shot = 0

function love.update()
  if not screenshotDir then
    if scenes[current].update then
      scenes[current].update()
    end
    return
  end
  shot = shot + 1
  if shot > #scenes then
    love.event.quit(0)
    return
  end
  current = shot
  scenes[shot].reset()
  playScript(shot)
  writeScreenshot(shot)
end

function love.draw()
  drawFrame()
end

function love.keypressed(key)
  local number = tonumber((key:gsub("^kp", "")))
  if number and scenes[number] then
    current = number
  elseif key == "r" then
    scenes[current].reset()
  elseif key == "escape" then
    love.event.quit()
  end
end

function love.mousepressed(x, y, button)
  if button == 1 and not screenshotDir then
    scenes[current].pressed(x, y, button)
  end
end

function love.mousemoved(x, y, dx, dy)
  if not screenshotDir then
    scenes[current].moved(x, y, dx, dy)
  end
end

function love.mousereleased(x, y, button)
  if button == 1 and not screenshotDir then
    scenes[current].released(x, y, button)
  end
end

function love.wheelmoved(x, y)
  if scenes[current].wheelmoved then
    scenes[current].wheelmoved(x, y)
  end
end
