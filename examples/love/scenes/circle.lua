-- Scene 5: circle and polygon.
--
-- polygonCircleCollideV(points, cx, cy, r) gives the overlap and the displacement (dx, dy) that moves
-- the circle out of the polygon; releasing the circle adds it to the centre, in one step even when the
-- centre is deep inside (the tutorial's version needed several).

return function(polygon, ui)
  local colors = ui.colors
  local scene = {
    title = "Circle and polygon",
    help = "Drag the circle into the polygon and release; the polygon's vertices, edges and body drag too."
      .. " Wheel: radius. R resets.",
  }

  local RESIDUE = 1e-9 -- pixels of overlap left after resolving that count as rounding, not overlap
  local START = { 330, 190, 560, 160, 660, 330, 540, 500, 300, 450 }

  function scene.reset()
    scene.points = ui.copy(START)
    scene.cx, scene.cy, scene.r = 780, 300, 50
    scene.grab = nil
    scene.last = nil
  end

  function scene.draw()
    local points, cx, cy, r = scene.points, scene.cx, scene.cy, scene.r
    local overlap, dx, dy, refusal = ui.ask(polygon.polygonCircleCollideV, points, cx, cy, r)
    local last = scene.last
    if last then
      ui.setColor(colors.orange, 0.45)
      love.graphics.setLineWidth(1)
      love.graphics.circle("line", last.cx, last.cy, r)
      ui.arrow(last.cx, last.cy, last.cx + last.dx, last.cy + last.dy, colors.red, 2)
    end

    ui.drawPolygon(points, overlap and colors.hit or colors.blue)
    ui.vertices(points, colors.blue, 4)
    if scene.grab and scene.grab ~= "circle" then
      ui.drawGrab(points, scene.grab)
    end

    ui.setColor(overlap and colors.hit or colors.orange, 0.35)
    love.graphics.circle("fill", cx, cy, r)
    ui.setColor(overlap and colors.hit or colors.orange)
    love.graphics.setLineWidth(scene.grab == "circle" and 3 or 2)
    love.graphics.circle("line", cx, cy, r)
    ui.dot(cx, cy, colors.orange, 4)
    if overlap then
      ui.setColor(colors.text, 0.7)
      love.graphics.setLineWidth(1)
      love.graphics.circle("line", cx + dx, cy + dy, r)
      ui.arrow(cx, cy, cx + dx, cy + dy, colors.red, 3)
    end

    local inside = polygon.polygonContains(points, cx, cy)
    local lines = {
      ("circle: centre (%s), radius %s"):format(ui.showAll(cx, cy), ui.show(r)),
      ("polygonContains(points, cx, cy) = %s"):format(ui.show(inside)),
    }
    if overlap then
      lines[#lines + 1] = { colors.red, "red: displacement, polygonCircleCollideV(points, cx, cy, r) =" }
      lines[#lines + 1] = { colors.red, "     " .. ui.showAll(overlap, dx, dy) }
      lines[#lines + 1] = { colors.dim, "release to apply it (thin circle: the result)" }
    else
      lines[#lines + 1] = ("polygonCircleCollideV(points, cx, cy, r) = %s"):format(ui.show(overlap))
    end
    if last then
      lines[#lines + 1] = ""
      lines[#lines + 1] = ("last release moved the circle by (%s)"):format(ui.showAll(last.dx, last.dy))
      lines[#lines + 1] = ("from a centre %s the polygon"):format(last.inside and "inside" or "outside")
      lines[#lines + 1] = ("then polygonCircleCollideV = %s")
        :format(ui.showAll(last.after, last.afterDx, last.afterDy))
    end
    if refusal then   -- the library refuses a concave polygon rather than answer wrong
      lines[#lines + 1] = { colors.yellow, refusal }
    elseif polygon.polygonType(points) ~= "convex" then
      lines[#lines + 1] = { colors.yellow, "the separating axis test needs a convex polygon" }
    end
    ui.panel(lines, 24, 40)
  end

  function scene.pressed(x, y)
    if ui.within(x, y, scene.cx, scene.cy, scene.r) then
      scene.grab = "circle"
      scene.last = nil
      return
    end
    scene.grab = ui.pick(polygon, scene.points, x, y)
  end

  function scene.moved(_, _, dx, dy)
    if scene.grab == "circle" then
      scene.cx, scene.cy = scene.cx + dx, scene.cy + dy
    elseif scene.grab then
      ui.drag(scene.points, scene.grab, dx, dy)
    end
  end

  function scene.released()
    if scene.grab ~= "circle" then
      scene.grab = nil
      return
    end
    scene.grab = nil
    local points, cx, cy, r = scene.points, scene.cx, scene.cy, scene.r
    local overlap, dx, dy = ui.ask(polygon.polygonCircleCollideV, points, cx, cy, r)
    if not overlap then
      return
    end
    scene.cx, scene.cy = cx + dx, cy + dy
    local after, afterDx, afterDy = polygon.polygonCircleCollideV(points, scene.cx, scene.cy, r)
    scene.last = {
      cx = cx, cy = cy, dx = dx, dy = dy, overlap = overlap,
      inside = polygon.polygonContains(points, cx, cy),
      after = after, afterDx = afterDx, afterDy = afterDy,
    }
  end

  function scene.wheelmoved(_, y)
    scene.r = math.max(5, math.min(200, scene.r + 5 * y))
  end

  -- Screenshot: drop the circle with its centre deep inside the polygon.
  scene.script = {
    { "press", 780, 300 },
    { "move", 540, 320 },
    { "release" },
  }

  function scene.check()
    local last = assert(scene.last, "scene 5: the release should have resolved a collision")
    assert(last.inside, "scene 5: the scripted drop should put the centre inside the polygon")
    assert(last.overlap > scene.r, "scene 5: the centre should be deeper than the radius")
    -- Up to rounding, as in scene 4: the moved centre is a rounded double.
    assert(not last.after or last.after <= RESIDUE,
      "scene 5: after one displacement the circle still overlaps: " .. ui.showAll(last.after, last.afterDx,
        last.afterDy))
  end

  scene.reset()
  return scene
end
