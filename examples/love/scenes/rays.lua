-- Scene 7: rays.
--
-- A rock with two caves in it (an outline with two holes, split once by polygonConvexParts) and
-- a thin wall, all one list of parts. From the eye, polygonRayCast(level, eye, target) gives line
-- of sight to the target (drag it): clear, or blocked at a hit point with the outward normal of
-- the edge hit, a hitscan's mark. A bullet (a small square) flies 45 pixels a frame, farther than
-- the thin wall is wide, moved each frame by polygonsCast: it stops where it first touches,
-- bounces along the normal, and never passes through the wall (a per-frame overlap test would).

return function(polygon, ui)
  local colors = ui.colors
  local scene = {
    title = "Rays",
    help = "Drag the target (or the eye) for line of sight; the bullet bounces by casts. R resets.",
  }

  local ROCK = { 430, 150, 760, 120, 900, 260, 880, 520, 640, 590, 470, 500, 540, 380, 420, 300 }
  local CAVES = {
    { 560, 220, 700, 200, 740, 300, 620, 320 },
    { 700, 400, 800, 360, 830, 470, 720, 500 },
  }
  local WALL = { 250, 330, 254, 330, 254, 590, 250, 590 }   -- 4 pixels thick
  local EYE, TARGET = { 110, 250 }, { 860, 560 }
  local BULLET = { 60, 470, 45, -9 }   -- centre x, y, then vx, vy: pixels and pixels a frame
  local HALF = 4                        -- the bullet is a square 8 pixels a side

  local level = assert(polygon.polygonConvexParts(ROCK, CAVES))
  local rockParts = #level
  level[#level + 1] = WALL
  -- the bullet's world: the level and four slabs around the field (x 24..936, y 150..600)
  local world = { { 0, 130, 960, 130, 960, 150, 0, 150 }, { 0, 600, 960, 600, 960, 620, 0, 620 },
    { 4, 150, 24, 150, 24, 600, 4, 600 }, { 936, 150, 956, 150, 956, 600, 936, 600 } }
  for _, part in ipairs(level) do world[#world + 1] = part end

  function scene.reset()
    scene.eye = { EYE[1], EYE[2] }
    scene.target = { TARGET[1], TARGET[2] }
    local x, y = BULLET[1], BULLET[2]
    scene.bullet = { x - HALF, y - HALF, x + HALF, y - HALF, x + HALF, y + HALF, x - HALF, y + HALF }
    scene.velocity = { BULLET[3], BULLET[4] }
    scene.trail = { x, y }
    scene.bounces, scene.wallHits, scene.frames, scene.wentInside = 0, 0, 0, false
    scene.grab = nil
  end

  -- One frame of the bullet: polygonsCast(world, bullet, move) gives where it first touches;
  -- move it that far (the fraction is stepped back so that it never overlaps), turn the velocity
  -- about the normal and spend the rest of the move the same way (at most four bounces a frame).
  local function stepBullet()
    local b, v = scene.bullet, scene.velocity
    local left = 1
    for _ = 1, 4 do
      local dx, dy = v[1] * left, v[2] * left
      local f, nx, ny = polygon.polygonsCast(world, b, dx, dy)
      if not f then
        polygon.polygonTranslate(b, dx, dy, b)
        break
      end
      polygon.polygonTranslate(b, f * dx, f * dy, b)
      scene.bounces = scene.bounces + 1
      if nx ~= 0 and b[1] < WALL[3] + 1 and b[3] > WALL[1] - 1 then   -- a side of the thin wall
        scene.wallHits = scene.wallHits + 1
      end
      local along = v[1] * nx + v[2] * ny
      v[1], v[2] = v[1] - 2 * along * nx, v[2] - 2 * along * ny
      left = left * (1 - f)
      scene.trail[#scene.trail + 1], scene.trail[#scene.trail + 2] = b[1] + HALF, b[2] + HALF
    end
    scene.trail[#scene.trail + 1], scene.trail[#scene.trail + 2] = b[1] + HALF, b[2] + HALF
    while #scene.trail > 2 * 40 do table.remove(scene.trail, 1); table.remove(scene.trail, 1) end
    if polygon.polygonsCollide(world, b) then scene.wentInside = true end
    scene.frames = scene.frames + 1
  end
  scene.update = stepBullet

  function scene.draw()
    for i, part in ipairs(level) do
      ui.fillPolygon(part, i % 2 == 0 and colors.blue or colors.purple, 0.45)
      ui.outlinePolygon(part, colors.dim, 0.6, 1)
    end
    ui.outlinePolygon(ROCK, colors.text, 1, 2)
    for _, cave in ipairs(CAVES) do ui.outlinePolygon(cave, colors.text, 1, 2) end
    ui.outlinePolygon(WALL, colors.text, 1, 1)

    local ex, ey, tx, ty = scene.eye[1], scene.eye[2], scene.target[1], scene.target[2]
    local f, nx, ny = polygon.polygonRayCast(level, ex, ey, tx, ty)
    love.graphics.setLineWidth(2)
    if f then
      local hx, hy = ex + (tx - ex) * f, ey + (ty - ey) * f
      ui.setColor(colors.green)
      love.graphics.line(ex, ey, hx, hy)
      ui.setColor(colors.red, 0.5)
      love.graphics.line(hx, hy, tx, ty)
      ui.dot(hx, hy, colors.red, 5)
      ui.arrow(hx, hy, hx + nx * 40, hy + ny * 40, colors.yellow, 2)
    else
      ui.setColor(colors.green)
      love.graphics.line(ex, ey, tx, ty)
    end
    ui.dot(ex, ey, colors.text, 8)
    ui.setColor(colors.orange)
    love.graphics.circle("line", tx, ty, 10)
    love.graphics.line(tx - 14, ty, tx + 14, ty)
    love.graphics.line(tx, ty - 14, tx, ty + 14)

    if #scene.trail >= 4 then
      ui.setColor(colors.orange, 0.6)
      love.graphics.setLineWidth(1)
      love.graphics.line(scene.trail)
    end
    ui.drawPolygon(scene.bullet, colors.orange)

    ui.panel({
      ("polygonConvexParts(rock, {cave1, cave2}): %d parts, + a wall 4 px thick"):format(rockParts),
      ("polygonRayCast(level, eye, target) = %s"):format(ui.showAll(f, nx, ny)),
      f and { colors.red, "line of sight blocked: hit point and normal" }
        or { colors.green, "clear line of sight" },
      ("bullet: polygonsCast(world, bullet, move), 45 px a frame: %d frames, %d bounces, %d off"
        .. " the thin wall"):format(scene.frames, scene.bounces, scene.wallHits),
    }, 24, 40)
  end

  function scene.pressed(x, y)
    if ui.within(x, y, scene.target[1], scene.target[2], 16) then
      scene.grab = scene.target
    elseif ui.within(x, y, scene.eye[1], scene.eye[2], 16) then
      scene.grab = scene.eye
    end
  end

  function scene.moved(_, _, dx, dy)
    if not scene.grab then return end
    scene.grab[1], scene.grab[2] = scene.grab[1] + dx, scene.grab[2] + dy
  end

  function scene.released()
    scene.grab = nil
  end

  -- Screenshot: drag the target behind the rock, then run the bullet 120 frames. The eye's ray
  -- must be blocked by the rock's left side; the bullet must bounce off the thin wall at least
  -- once and never be inside the level after a frame.
  scene.script = {
    { "press", TARGET[1], TARGET[2] },
    { "move", 870, 330 },
    { "release" },
  }
  scene.scriptFrames = 120

  function scene.check()
    local ex, ey, tx, ty = scene.eye[1], scene.eye[2], scene.target[1], scene.target[2]
    local f, nx, ny = polygon.polygonRayCast(level, ex, ey, tx, ty)
    assert(f and f > 0 and f < 1, "scene 7: the rock should block the line of sight")
    assert(nx < 0, "scene 7: the normal of the rock's left side points left, got " .. ui.showAll(nx, ny))
    assert(scene.wallHits >= 1, "scene 7: the bullet should bounce off the thin wall")
    assert(not scene.wentInside, "scene 7: the bullet ended a frame overlapping the level")
  end

  scene.reset()
  return scene
end
