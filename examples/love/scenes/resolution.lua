-- Scene 4: collision resolution.
--
-- The polygon you drag is the displaced one (the second argument), the other one is static.
-- polygonsCollideV(static, displaced) gives the overlap and the displacement (dx, dy) that moves the
-- displaced polygon out; releasing the mouse adds it to every vertex, in one step.

return function(polygon, ui)
  local colors = ui.colors
  local scene = {
    title = "Collision resolution",
    help = "Drag a vertex, an edge or the body of a polygon into the other one and release. R resets.",
  }

  local START = {
    { 220, 250, 420, 220, 500, 380, 380, 520, 200, 440 },
    { 620, 250, 780, 290, 750, 450, 600, 420 },
  }
  local NAMES = { "A", "B" }
  local RESIDUE = 1e-9 -- pixels of overlap left after resolving that count as rounding, not overlap
  local COLORS = { colors.blue, colors.orange }

  function scene.reset()
    scene.shapes = { ui.copy(START[1]), ui.copy(START[2]) }
    scene.moving = 2
    scene.grab = nil
    scene.last = nil
  end

  local function staticIndex()
    return 3 - scene.moving
  end

  local function drawName(index)
    local cx, cy = polygon.polygonCenter(scene.shapes[index])
    if cx then
      ui.label(NAMES[index], cx - 5, cy - 10, colors.text, "large")
    end
  end

  function scene.draw()
    local s, m = staticIndex(), scene.moving
    local static, moving = scene.shapes[s], scene.shapes[m]
    local overlap, dx, dy, refusal = ui.ask(polygon.polygonsCollideV, static, moving)

    local last = scene.last
    if last then
      -- Where the polygon was dropped, and the displacement that was applied on release.
      ui.outlinePolygon(last.dropped, COLORS[last.moving], 0.45, 1)
    end

    ui.drawPolygon(static, COLORS[s])
    ui.drawPolygon(moving, overlap and colors.hit or COLORS[m])
    ui.vertices(static, COLORS[s], 4)
    ui.vertices(moving, COLORS[m], 4)
    if overlap then
      ui.outlinePolygon(ui.translated(moving, dx, dy), colors.text, 0.7, 1)
    end
    if scene.grab then
      ui.drawGrab(moving, scene.grab)
    end

    local sx, sy = polygon.polygonCenter(static)
    local mx, my = polygon.polygonCenter(moving)
    if sx and mx then
      ui.arrow(sx, sy, mx, my, colors.green, 2)
      if last then
        local fx, fy = polygon.polygonCenter(last.dropped)
        ui.arrow(fx, fy, fx + last.dx, fy + last.dy, colors.red, 3)
      end
      if overlap then
        ui.arrow(mx, my, mx + dx, my + dy, colors.red, 3)
      end
    end
    drawName(1)
    drawName(2)

    local call = ("polygonsCollideV(%s, %s)"):format(NAMES[s], NAMES[m])
    local lines = {
      ("static: %s   displaced (dragged): %s"):format(NAMES[s], NAMES[m]),
      { colors.green, "green: polygonCenter(static) to polygonCenter(displaced)" },
    }
    if overlap then
      lines[#lines + 1] = { colors.red, ("red: displacement, %s ="):format(call) }
      lines[#lines + 1] = { colors.red, "     " .. ui.showAll(overlap, dx, dy) }
      lines[#lines + 1] = { colors.dim, "release to apply it (thin outline: the result)" }
    else
      lines[#lines + 1] = ("%s = %s"):format(call, ui.show(overlap))
    end
    if last then
      lines[#lines + 1] = ""
      lines[#lines + 1] = ("last release moved %s by (%s)")
        :format(NAMES[last.moving], ui.showAll(last.dx, last.dy))
      lines[#lines + 1] = ("then polygonsCollideV(%s, %s) = %s"):format(NAMES[3 - last.moving],
        NAMES[last.moving], ui.showAll(last.after, last.afterDx, last.afterDy))
    end
    if refusal then   -- the library refuses a concave polygon rather than answer wrong
      lines[#lines + 1] = { colors.yellow, refusal }
    elseif polygon.polygonType(static) ~= "convex" or polygon.polygonType(moving) ~= "convex" then
      lines[#lines + 1] = { colors.yellow, "the separating axis test needs convex polygons" }
    end
    ui.panel(lines, 24, 40)
  end

  function scene.pressed(x, y)
    -- The shape drawn on top (B) gets the first chance.
    local grab, index = ui.pickTopmost(polygon, scene.shapes, x, y)
    if grab then scene.grab, scene.moving = grab, index end   -- a miss keeps the moving shape
  end

  function scene.moved(_, _, dx, dy)
    if scene.grab then
      ui.drag(scene.shapes[scene.moving], scene.grab, dx, dy)
    end
  end

  function scene.released()
    if not scene.grab then
      return
    end
    scene.grab = nil
    local static, moving = scene.shapes[staticIndex()], scene.shapes[scene.moving]
    local overlap, dx, dy = ui.ask(polygon.polygonsCollideV, static, moving)
    if not overlap then
      return
    end
    local dropped = ui.copy(moving)
    ui.move(moving, dx, dy)
    local after, afterDx, afterDy = polygon.polygonsCollideV(static, moving)
    scene.last = {
      moving = scene.moving, dropped = dropped, overlap = overlap, dx = dx, dy = dy,
      after = after, afterDx = afterDx, afterDy = afterDy,
    }
  end

  -- Screenshot: drag B by its body deep into A and release.
  scene.script = {
    { "press", 690, 350 },
    { "move", 480, 380 },
    { "release" },
  }

  function scene.check()
    local last = assert(scene.last, "scene 4: the release should have resolved a collision")
    assert(last.overlap > 20, "scene 4: the scripted drag should overlap deeply")
    -- (dx, dy) is rounded to doubles and so are the moved vertices: the shapes end up touching up to
    -- a rounding residue, which polygonsCollideV (exact) may still report as a tiny overlap.
    assert(not last.after or last.after <= RESIDUE,
      "scene 4: after one displacement the polygons still overlap: " .. ui.showAll(last.after, last.afterDx,
        last.afterDy))
  end

  scene.reset()
  return scene
end
