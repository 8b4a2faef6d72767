-- Scene 6: concave shapes.
--
-- A level of two concave outlines, a U-shaped floor and a tile-map outline whose tiles meet at
-- corners, split once by polygonConvexParts (each part drawn in its own shade, the seams between
-- them thin). The level is one compound shape: the list of all their parts. Drag the crate or the
-- ball into it and release: polygonsCollideV(level, crate) and polygonCircleCollideV(level, ...)
-- give the push out, which is never along a seam.

return function(polygon, ui)
  local colors = ui.colors
  local scene = {
    title = "Concave",
    help = "Drag the crate or the ball into the floor or the tiles and release. R resets.",
  }

  local U = { 90, 330, 170, 330, 170, 500, 430, 500, 430, 330, 510, 330, 510, 590, 90, 590 }
  -- a 4 x 4 tile map, 45 pixels a tile, with three pinch points (tiles meeting at a corner)
  local TILE, TX, TY = 45, 600, 390
  local TILES = {}
  for i, v in ipairs({ 0, 0, 1, 0, 1, 1, 2, 1, 2, 0, 3, 0, 3, 1, 4, 1, 4, 2, 3, 2, 3, 3, 4, 3,
    4, 4, 3, 4, 3, 3, 2, 3, 2, 2, 1, 2, 1, 3, 0, 3, 0, 2, 1, 2, 1, 1, 0, 1 }) do
    TILES[i] = v * TILE + (i % 2 == 1 and TX or TY)
  end
  local CRATE = { 300, 220, 360, 220, 360, 280, 300, 280 }
  local BALL = { 820, 250, 24 }

  local outlines = { U, TILES }
  local level, counts = {}, {}
  for k, outline in ipairs(outlines) do
    local parts = assert(polygon.polygonConvexParts(outline))
    counts[k] = #parts
    for _, part in ipairs(parts) do level[#level + 1] = part end
  end

  function scene.reset()
    scene.crate = ui.copy(CRATE)
    scene.ball = { BALL[1], BALL[2], BALL[3] }
    scene.grab, scene.what, scene.last = nil, nil, nil
  end

  -- the push the dragged shape would get now: overlap, dx, dy or false
  local function push(what)
    if what == "ball" then
      return polygon.polygonCircleCollideV(level, scene.ball[1], scene.ball[2], scene.ball[3])
    end
    return polygon.polygonsCollideV(level, scene.crate)
  end

  function scene.draw()
    for i, part in ipairs(level) do
      ui.fillPolygon(part, i % 2 == 0 and colors.blue or colors.purple, 0.45)
      ui.outlinePolygon(part, colors.dim, 0.8, 1)
    end
    for _, outline in ipairs(outlines) do
      ui.outlinePolygon(outline, colors.text, 1, 2)
    end
    local crateHit, cdx, cdy = push("crate")
    ui.drawPolygon(scene.crate, crateHit and colors.hit or colors.orange)
    local ballHit, bdx, bdy = push("ball")
    local bx, by, r = scene.ball[1], scene.ball[2], scene.ball[3]
    ui.setColor(ballHit and colors.hit or colors.green, 0.5)
    love.graphics.circle("fill", bx, by, r)
    ui.setColor(colors.text)
    love.graphics.circle("line", bx, by, r)
    local cx, cy = polygon.polygonCenter(scene.crate)
    if crateHit then ui.arrow(cx, cy, cx + cdx, cy + cdy, colors.red, 3) end
    if ballHit then ui.arrow(bx, by, bx + bdx, by + bdy, colors.red, 3) end

    local lines = {
      ("polygonConvexParts: U floor %d parts, tiles %d parts (thin lines: seams)")
        :format(counts[1], counts[2]),
      "level = all parts, one compound shape",
      ("polygonsCollideV(level, crate) = %s"):format(ui.showAll(crateHit, cdx, cdy)),
      ("polygonCircleCollideV(level, ball) = %s"):format(ui.showAll(ballHit, bdx, bdy)),
    }
    local last = scene.last
    if last then
      lines[#lines + 1] = ""
      lines[#lines + 1] = { colors.red, ("last release pushed the %s by (%s)")
        :format(last.what, ui.showAll(last.dx, last.dy)) }
      lines[#lines + 1] = ("then it collides: %s"):format(ui.show(last.after))
    end
    ui.panel(lines, 24, 40)
  end

  function scene.pressed(x, y)
    if ui.within(x, y, scene.ball[1], scene.ball[2], scene.ball[3]) then
      scene.grab, scene.what = { kind = "body" }, "ball"
    elseif polygon.polygonContains(scene.crate, x, y) then
      scene.grab, scene.what = { kind = "body" }, "crate"
    end
  end

  function scene.moved(_, _, dx, dy)
    if not scene.grab then return end
    if scene.what == "ball" then
      scene.ball[1], scene.ball[2] = scene.ball[1] + dx, scene.ball[2] + dy
    else
      ui.drag(scene.crate, scene.grab, dx, dy)
    end
  end

  function scene.released()
    if not scene.grab then return end
    scene.grab = nil
    local what = scene.what
    local overlap, dx, dy = push(what)
    if not overlap then return end
    if what == "ball" then
      scene.ball[1], scene.ball[2] = scene.ball[1] + dx, scene.ball[2] + dy
    else
      ui.move(scene.crate, dx, dy)
    end
    scene.last = { what = what, overlap = overlap, dx = dx, dy = dy, after = push(what) }
  end

  -- Screenshot: sink the crate 8 pixels into the U's floor (its bottom edge at y = 508, the floor
  -- at 500) across the part seams there, and release: it must go straight up by 8.
  scene.script = {
    { "press", 330, 250 },
    { "move", 330, 478 },
    { "release" },
  }

  function scene.check()
    local last = assert(scene.last, "scene 6: the release should have resolved a collision")
    assert(last.what == "crate", "scene 6: the script drags the crate")
    assert(last.dx == 0 and math.abs(last.dy + 8) < 1e-9,
      "scene 6: a crate sunk 8 into the floor goes straight up by 8, got " .. ui.showAll(last.dx, last.dy))
    assert(not last.after, "scene 6: after the push the crate still collides")
  end

  scene.reset()
  return scene
end
