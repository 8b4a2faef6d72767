-- Scene 2: point in polygon.
--
-- The tutorial draws where the horizontal line through the red point crosses the polygon's edges:
-- purple when the crossing is right of the point (it counts), green when left. The demo does not
-- compute crossings itself. For one edge A-B it builds the quadrilateral A, B, (m, By), (m, Ay):
-- its two horizontal edges are never crossed, and its vertical edge at x = m is crossed exactly
-- when A-B's y-test passes, counting when x <= m. polygonContains on that quadrilateral is odd, so
--   m < x: polygonContains = the edge's crossing counts (purple),
--   m > x: polygonContains = the edge is crossed but the crossing does not count (green).
-- Where the crossing sits is where the first answer flips as x moves: the demo bisects for it.

return function(polygon, ui)
  local colors = ui.colors
  local scene = {
    title = "Point in polygon",
    help = "Drag the red point or the polygon's vertices. R resets.",
  }

  -- A comb opening downwards: a horizontal line can cross it many times.
  local START = {
    180, 180, 780, 180, 780, 520, 660, 520, 660, 260, 560, 260, 560, 470, 420, 470,
    420, 260, 320, 260, 320, 520, 180, 520,
  }

  function scene.reset()
    scene.points = ui.copy(START)
    scene.shape = polygon.Polygon(scene.points) -- .points is scene.points itself, not a copy
    scene.px, scene.py = 360, 580
    scene.grab = nil
  end

  local function edgeCounts(x1, y1, x2, y2, x, y)
    return polygon.polygonContains({ x1, y1, x2, y2, x - 1, y2, x - 1, y1 }, x, y)
  end

  local function edgeCrossedLeft(x1, y1, x2, y2, x, y)
    return polygon.polygonContains({ x1, y1, x2, y2, x + 1, y2, x + 1, y1 }, x, y)
  end

  -- The largest double t <= the edge's x at height y, found from polygonContains alone.
  local function crossingX(x1, y1, x2, y2, y)
    local lo, hi = math.min(x1, x2), math.max(x1, x2) + 1
    for _ = 1, 200 do
      local mid = lo + (hi - lo) / 2
      if mid == lo or mid == hi then
        break
      end
      if edgeCounts(x1, y1, x2, y2, mid, y) then
        lo = mid
      else
        hi = mid
      end
    end
    return lo
  end

  -- Every crossed edge as { x = crossing x, right = counts }, from polygon.lua.
  local function crossings(points, x, y)
    local result = {}
    local n = #points
    for i = 1, n, 2 do
      local j = i + 2 > n and 1 or i + 2
      local x1, y1, x2, y2 = points[i], points[i + 1], points[j], points[j + 1]
      local right = edgeCounts(x1, y1, x2, y2, x, y)
      if right or edgeCrossedLeft(x1, y1, x2, y2, x, y) then
        result[#result + 1] = { x = crossingX(x1, y1, x2, y2, y), right = right }
      end
    end
    return result
  end
  scene.crossings = crossings

  function scene.draw()
    local points, px, py = scene.points, scene.px, scene.py
    local inside = scene.shape:contains(px, py)
    ui.drawPolygon(points, colors.blue, inside and 0.5 or 0.3)
    ui.vertices(points, colors.blue, 5)
    ui.drawGrab(points, scene.grab ~= "point" and scene.grab or nil)

    ui.setColor(colors.dim, 0.6)
    love.graphics.setLineWidth(1)
    love.graphics.line(0, py, ui.WIDTH, py)
    ui.arrow(px, py, ui.WIDTH - 4, py, colors.purple, 1)

    local right, left = 0, 0
    for _, crossing in ipairs(crossings(points, px, py)) do
      if crossing.right then
        right = right + 1
        ui.dot(crossing.x, py, colors.purple, 7)
      else
        left = left + 1
        ui.dot(crossing.x, py, colors.green, 7)
      end
    end
    ui.dot(px, py, colors.red, 8)
    if scene.grab == "point" then
      ui.setColor(colors.yellow)
      love.graphics.setLineWidth(2)
      love.graphics.circle("line", px, py, ui.GRAB_RADIUS + 2)
    end

    ui.panel({
      ("red point (%s)"):format(ui.showAll(px, py)),
      { colors.purple, ("purple: crossings right of the point: %d (%s)"):format(right,
        right % 2 == 1 and "odd" or "even") },
      { colors.green, ("green: crossings left of the point: %d"):format(left) },
      ("polygonContains(points, x, y) = %s"):format(ui.show(polygon.polygonContains(points, px, py))),
      ("Polygon(points):contains(x, y) = %s"):format(ui.show(inside)),
      { inside and colors.green or colors.red, inside and "inside" or "outside" },
    }, 24, 40)
  end

  function scene.pressed(x, y)
    if ui.within(x, y, scene.px, scene.py, ui.GRAB_RADIUS + 2) then
      scene.grab = "point"
    else
      scene.grab = ui.pickVertex(scene.points, x, y)
    end
  end

  function scene.moved(_, _, dx, dy)
    if scene.grab == "point" then
      scene.px, scene.py = scene.px + dx, scene.py + dy
    elseif scene.grab then
      ui.drag(scene.points, scene.grab, dx, dy)
    end
  end

  function scene.released()
    scene.grab = nil
  end

  -- Screenshot: drag the point into the left tooth, then pull a vertex of the right tooth down.
  scene.script = {
    { "press", 360, 580 },
    { "move", 250, 390 },
    { "release" },
    { "press", 660, 520 },
    { "move", 700, 560 },
    { "release" },
  }

  function scene.check()
    local right = 0
    for _, crossing in ipairs(crossings(scene.points, scene.px, scene.py)) do
      if crossing.right then
        right = right + 1
      end
    end
    assert(right == 5, "scene 2: expected 5 crossings right of the point, got " .. right)
    assert(scene.shape:contains(scene.px, scene.py), "scene 2: the point should be inside")
  end

  scene.reset()
  return scene
end
