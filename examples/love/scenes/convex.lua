-- Scene 1: convex or concave.
--
-- Each vertex v is marked by the sign of the tutorial's cross product of its adjacent edges,
-- (prev - v) x (next - v): green when negative, red when positive. The demo does not compute that
-- product itself. For the triangle (prev, v, next) the shoelace sum equals (v - prev) x (next - prev)
-- = -((prev - v) x (next - v)), so
--   polygonWindingOrder(triangle) == "cw"  (shoelace > 0)  <=>  cross < 0  (green),
--   polygonWindingOrder(triangle) == "ccw" (shoelace < 0)  <=>  cross > 0  (red),
--   nil (collinear)                                        <=>  cross = 0  (grey),
-- and |cross| = 2 * polygonArea(triangle).

return function(polygon, ui)
  local colors = ui.colors
  local scene = {
    title = "Convex or concave",
    help = "Drag the vertices. R resets.",
  }

  -- A clockwise (on screen) hexagon: every vertex starts green.
  local START = { 480, 220, 700, 170, 880, 280, 860, 480, 650, 560, 460, 440 }

  function scene.reset()
    scene.points = ui.copy(START)
    scene.grab = nil
  end

  -- Sign and value of (prev - v) x (next - v) at the vertex whose x is points[i], from polygon.lua.
  local function vertexCross(points, i)
    local n = #points
    local p = (i - 3) % n + 1
    local q = (i + 1) % n + 1
    local triangle = { points[p], points[p + 1], points[i], points[i + 1], points[q], points[q + 1] }
    local winding = polygon.polygonWindingOrder(triangle)
    if winding == "cw" then
      return -1, -2 * polygon.polygonArea(triangle)
    elseif winding == "ccw" then
      return 1, 2 * polygon.polygonArea(triangle)
    end
    return 0, 0
  end

  local function vertices(count)
    return count == 1 and "1 vertex" or count .. " vertices"
  end

  function scene.draw()
    local points = scene.points
    ui.drawPolygon(points, colors.blue)
    ui.drawGrab(points, scene.grab)
    local negative, positive = 0, 0
    for i = 1, #points, 2 do
      local sign, cross = vertexCross(points, i)
      local color = colors.grey
      if sign < 0 then
        color, negative = colors.green, negative + 1
      elseif sign > 0 then
        color, positive = colors.red, positive + 1
      end
      ui.dot(points[i], points[i + 1], color, 8)
      ui.label(ui.show(cross), points[i] + 11, points[i + 1] - 22, color, "small")
    end
    ui.panel({
      ("polygonWindingOrder(points) = %s"):format(ui.show(polygon.polygonWindingOrder(points))),
      ("polygonArea(points) = %s"):format(ui.show(polygon.polygonArea(points))),
      ("polygonType(points) = %s"):format(ui.show(polygon.polygonType(points))),
      "",
      "At each vertex v: (prev - v) x (next - v)",
      { colors.green, ("  green: negative (%s)"):format(vertices(negative)) },
      { colors.red, ("  red: positive (%s)"):format(vertices(positive)) },
      { colors.dim, "sign from polygonWindingOrder, size from polygonArea" },
      { colors.dim, "of the triangle (prev, v, next)" },
    }, 24, 60)
  end

  function scene.pressed(x, y)
    scene.grab = ui.pickVertex(scene.points, x, y)
  end

  function scene.moved(_, _, dx, dy)
    if scene.grab then
      ui.drag(scene.points, scene.grab, dx, dy)
    end
  end

  function scene.released()
    scene.grab = nil
  end

  -- Screenshot: pull the top vertex (700, 170) down into the hexagon, making it concave.
  scene.script = {
    { "press", 700, 170 },
    { "move", 685, 350 },
    { "release" },
  }

  function scene.check()
    assert(polygon.polygonType(scene.points) == "concave",
      "scene 1: the dent should make the polygon concave")
    local sign = vertexCross(scene.points, 3)
    assert(sign > 0, "scene 1: the dented vertex should be red (positive cross product)")
  end

  scene.reset()
  return scene
end
