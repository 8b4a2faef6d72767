-- Scene 7: rays.
--
-- A rock with two caves in it (an outline with two holes, split once by polygonConvexParts) and
-- a thin wall, all one list of parts. From the eye, polygonRayCast(level, eye, target) gives line
-- of sight to the target (drag it): clear, or blocked at a hit point with the outward normal of
-- the edge hit, a hitscan's mark. A bullet flies 45 pixels a frame, farther than the thin wall is
-- wide, moved each frame by casting its step: it stops at what it hits, bounces along the
-- normal, and never passes through the wall (a per-frame overlap test would, on most frames).

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
  local FIELD = { 24, 150, 936, 600 }   -- the bullet bounces inside this box too: x0, y0, x1, y1
  local EYE, TARGET = { 110, 250 }, { 860, 560 }
  local BULLET = { 60, 470, 45, -9 }   -- x, y, vx, vy: pixels and pixels a frame
  local SKIN = 0.01   -- a hit point is left this far out along the normal, off the boundary

  local level = assert(polygon.polygonConvexParts(ROCK, CAVES))
  local rockParts = #level
  level[#level + 1] = WALL

  -- true when (x, y) lies strictly inside the level: a zero-length ray from it answers 0
  local function inside(x, y)
    return polygon.polygonRayCast(level, x, y, x, y) == 0
  end

  function scene.reset()
    scene.eye = { EYE[1], EYE[2] }
    scene.target = { TARGET[1], TARGET[2] }
    scene.bullet = { BULLET[1], BULLET[2], BULLET[3], BULLET[4] }
    scene.trail = { BULLET[1], BULLET[2] }
    scene.bounces, scene.wallHits, scene.frames, scene.wentInside = 0, 0, 0, false
    scene.grab = nil
  end

  -- One frame of the bullet: cast its step against the level and the field's sides, move to the
  -- first hit (SKIN out along the normal), turn the velocity about the normal and spend the rest
  -- of the step the same way (at most four bounces a frame).
  local function stepBullet()
    local b = scene.bullet
    local left = 1
    for _ = 1, 4 do
      local x, y = b[1], b[2]
      local tx, ty = x + b[3] * left, y + b[4] * left
      local f, nx, ny = polygon.polygonRayCast(level, x, y, tx, ty)
      -- the field's sides: the first one the step leaves through (plain floats: a box's sides)
      local side, sx, sy = false, 0, 0
      local across = tx < FIELD[1] and FIELD[1] or tx > FIELD[3] and FIELD[3]
      if across then side, sx = (across - x) / (tx - x), tx < x and 1 or -1 end
      local down = ty < FIELD[2] and FIELD[2] or ty > FIELD[4] and FIELD[4]
      if down and (not side or (down - y) / (ty - y) < side) then
        side, sx, sy = (down - y) / (ty - y), 0, ty < y and 1 or -1
      end
      if side and (not f or side < f) then
        f, nx, ny = side, sx, sy
      elseif f then
        scene.bounces = scene.bounces + 1
        -- the wall is the last part: is the hit point on it?
        local hx = x + (tx - x) * f
        if hx >= WALL[1] - 1 and hx <= WALL[3] + 1 then scene.wallHits = scene.wallHits + 1 end
      end
      if not f then
        b[1], b[2] = tx, ty
        break
      end
      b[1], b[2] = x + (tx - x) * f + nx * SKIN, y + (ty - y) * f + ny * SKIN
      local along = b[3] * nx + b[4] * ny
      b[3], b[4] = b[3] - 2 * along * nx, b[4] - 2 * along * ny
      left = left * (1 - f)
      scene.trail[#scene.trail + 1], scene.trail[#scene.trail + 2] = b[1], b[2]
    end
    scene.trail[#scene.trail + 1], scene.trail[#scene.trail + 2] = b[1], b[2]
    while #scene.trail > 2 * 40 do table.remove(scene.trail, 1); table.remove(scene.trail, 1) end
    if inside(b[1], b[2]) then scene.wentInside = true end
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
    ui.dot(scene.bullet[1], scene.bullet[2], colors.orange, 4)

    ui.panel({
      ("polygonConvexParts(rock, {cave1, cave2}): %d parts, + a wall 4 px thick"):format(rockParts),
      ("polygonRayCast(level, eye, target) = %s"):format(ui.showAll(f, nx, ny)),
      f and { colors.red, "line of sight blocked: hit point and normal" }
        or { colors.green, "clear line of sight" },
      ("bullet: 45 px a frame, %d frames, %d bounces, %d off the thin wall"):format(scene.frames,
        scene.bounces, scene.wallHits),
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
    assert(not scene.wentInside, "scene 7: the bullet went inside the level")
  end

  scene.reset()
  return scene
end
