-- LÖVE 11 configuration for the polygon.lua demos.

function love.conf(t)
  t.identity = "polygon-lua-demos"
  t.version = "11.4"
  t.window.title = "polygon.lua demos"
  t.window.width = 960
  t.window.height = 640
  t.window.resizable = false
  t.window.stencil = 8 -- ui.fillPolygon fills concave polygons through the stencil buffer
  -- The demos make no sound and read no joystick; skipping them keeps headless runs quiet.
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
  t.modules.physics = false
  t.modules.video = false
end
