rockspec_format = "3.0"
package = "polygon"
version = "scm-1"
source = {
  url = "git+https://github.com/polygon-lua/polygon.lua.git",
}
description = {
  summary = "Polygon geometry for games: winding, area, convexity, point in polygon, SAT collision",
  detailed = [[
    Pure Lua over flat point arrays {x1, y1, x2, y2, ...} (the form love.graphics.polygon
    takes): winding order, area, convex or concave, centre and centroid, point in polygon,
    separating-axis collision of convex polygons with a minimum translation vector, and convex
    polygon against circle. Every sign it decides is exact; per-frame calls allocate nothing.
  ]],
  homepage = "https://github.com/polygon-lua/polygon.lua",
  license = "MIT",
  labels = { "geometry", "polygon", "collision", "love2d", "gamedev" },
}
dependencies = {
  "lua >= 5.1",
}
build = {
  type = "builtin",
  modules = {
    polygon = "polygon.lua",
    ["polygon.kernel"] = "polygon/kernel.lua",
    ["polygon.check"] = "polygon/check.lua",
    ["polygon.measures"] = "polygon/measures.lua",
    ["polygon.contains"] = "polygon/contains.lua",
    ["polygon.sat"] = "polygon/sat.lua",
    ["polygon.circle"] = "polygon/circle.lua",
    ["polygon.object"] = "polygon/object.lua",
    ["polygon.convex"] = "polygon/convex.lua",
    ["polygon.monotone"] = "polygon/monotone.lua",
    ["polygon.nodes"] = "polygon/nodes.lua",
    ["polygon.order"] = "polygon/order.lua",
    ["polygon.places"] = "polygon/places.lua",
    ["polygon.sweep"] = "polygon/sweep.lua",
    ["polygon.rects"] = "polygon/rects.lua",
    ["polygon.triangulate"] = "polygon/triangulate.lua",
    ["polygon.views"] = "polygon/views.lua",
    ["polygon.faces"] = "polygon/faces.lua",
    ["polygon.compound"] = "polygon/compound.lua",
    ["polygon.collide"] = "polygon/collide.lua",
    ["polygon.transform"] = "polygon/transform.lua",
    ["polygon.raycast"] = "polygon/raycast.lua",
    ["polygon.rayring"] = "polygon/rayring.lua",
    ["polygon.circleray"] = "polygon/circleray.lua",
    ["polygon.closest"] = "polygon/closest.lua",
    ["polygon.casts"] = "polygon/casts.lua",
    ["polygon.circlecast"] = "polygon/circlecast.lua",
  },
}
test = {
  type = "busted",
}
