-- Scene 3: polygon collision (separating axis test), without resolution.

return function(polygon, ui)
  local colors = ui.colors
  local scene = {
    title = "Polygon collision",
    help = "Drag a vertex, an edge or the body of either polygon. R resets.",
  }

  local START_A = { 200, 230, 380, 180, 460, 330, 330, 470, 180, 400 }
  local START_B = { 620, 220, 800, 300, 690, 470 }

  function scene.reset()
    scene.shapes = { ui.copy(START_A), ui.copy(START_B) }
    scene.grab, scene.grabbed = nil, nil
  end

  function scene.draw()
    local a, b = scene.shapes[1], scene.shapes[2]
    local colliding, _, _, refusal = ui.ask(polygon.polygonsCollide, a, b)
    ui.drawPolygon(a, colliding and colors.hit or colors.blue, colliding and 0.45 or 0.35)
    ui.drawPolygon(b, colliding and colors.hit or colors.orange, colliding and 0.45 or 0.35)
    ui.vertices(a, colors.blue, 4)
    ui.vertices(b, colors.orange, 4)
    if scene.grab then
      ui.drawGrab(scene.shapes[scene.grabbed], scene.grab)
    end
    local typeA, typeB = polygon.polygonType(a), polygon.polygonType(b)
    local withA, withB = ui.ask(polygon.polygonCollidesWith, a, b), ui.ask(polygon.polygonCollidesWith, b, a)
    local lines = {
      { colors.blue, ("A: polygonType = %s"):format(ui.show(typeA)) },
      { colors.orange, ("B: polygonType = %s"):format(ui.show(typeB)) },
      ("polygonCollidesWith(A, B) = %s   (axes of A)"):format(ui.show(withA)),
      ("polygonCollidesWith(B, A) = %s   (axes of B)"):format(ui.show(withB)),
      { colliding and colors.hit or colors.text,
        ("polygonsCollide(A, B) = %s"):format(ui.show(colliding)) },
    }
    if refusal then   -- the library refuses a concave polygon rather than answer wrong
      lines[#lines + 1] = { colors.yellow, refusal }
    elseif typeA ~= "convex" or typeB ~= "convex" then
      lines[#lines + 1] = { colors.yellow, "the separating axis test needs convex polygons" }
    end
    ui.panel(lines, 24, 40)
  end

  function scene.pressed(x, y)
    -- The shape drawn on top (B) gets the first chance.
    scene.grab, scene.grabbed = ui.pickTopmost(polygon, scene.shapes, x, y)
  end

  function scene.moved(_, _, dx, dy)
    if scene.grab then
      ui.drag(scene.shapes[scene.grabbed], scene.grab, dx, dy)
    end
  end

  function scene.released()
    scene.grab, scene.grabbed = nil, nil
  end

  -- Screenshot: drag B by its body onto A, then pull one of A's edges towards B.
  scene.script = {
    { "press", 700, 330 },
    { "move", 500, 340 },
    { "release" },
    { "press", 395, 400 },
    { "move", 415, 395 },
    { "release" },
  }

  function scene.check()
    assert(polygon.polygonsCollide(scene.shapes[1], scene.shapes[2]), "scene 3: the polygons should collide")
  end

  scene.reset()
  return scene
end
