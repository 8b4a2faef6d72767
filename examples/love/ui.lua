-- Drawing and dragging helpers shared by the scenes.
--
-- Nothing here decides a geometric fact that a scene shows: the scenes ask polygon.lua for
-- those. This file only draws shapes and works out which handle the mouse grabbed.

local ui = {}

ui.WIDTH, ui.HEIGHT = 960, 640
ui.GRAB_RADIUS = 10 -- pixels: how close the mouse must be to grab a vertex or an edge

ui.colors = {
  background = { 0.11, 0.12, 0.15 },
  text = { 0.92, 0.92, 0.92 },
  dim = { 0.60, 0.62, 0.68 },
  panel = { 0.05, 0.05, 0.07, 0.85 },
  blue = { 0.25, 0.50, 0.95 },
  orange = { 0.95, 0.60, 0.20 },
  hit = { 0.90, 0.25, 0.30 },
  red = { 0.95, 0.22, 0.22 },
  green = { 0.25, 0.85, 0.35 },
  purple = { 0.75, 0.35, 0.95 },
  grey = { 0.65, 0.65, 0.65 },
  yellow = { 0.95, 0.85, 0.30 },
}

local fonts = {}

--- Loads the fonts; call once from love.load (love.graphics must be ready).
function ui.load()
  fonts.small = love.graphics.newFont(13)
  fonts.normal = love.graphics.newFont(15)
  fonts.large = love.graphics.newFont(20)
end

function ui.font(size)
  return fonts[size or "normal"]
end

local function setColor(color, alpha)
  love.graphics.setColor(color[1], color[2], color[3], alpha or color[4] or 1)
end
ui.setColor = setColor

--- Calls a collision function of polygon.lua. A shape it refuses (a polygon dragged concave)
-- gives false, nil, nil and the refusal's message (without the file and line), which the
-- scenes show instead of an answer.
function ui.ask(fn, ...)
  local ok, a, b, c = pcall(fn, ...)
  if ok then return a, b, c, nil end
  return false, nil, nil, (tostring(a):gsub("^[^:]*:%d+: ", ""))
end

--- Formats a value returned by polygon.lua the way Lua would write it.
function ui.show(value)
  local kind = type(value)
  if kind == "string" then
    return ("%q"):format(value)
  elseif kind == "number" then
    if value == math.floor(value) and math.abs(value) < 1e15 then
      return ("%d"):format(value)
    end
    if value ~= 0 and math.abs(value) < 0.001 then
      return ("%.3g"):format(value) -- a rounding residue must not read as 0.000
    end
    return ("%.3f"):format(value)
  end
  return tostring(value)
end

--- Lists several return values: ui.showAll(1, 2) is "1, 2".
function ui.showAll(...)
  local parts = {}
  for i = 1, select("#", ...) do
    parts[i] = ui.show((select(i, ...)))
  end
  return table.concat(parts, ", ")
end

--- Copies a flat point array (the scenes keep their start shapes untouched).
function ui.copy(points)
  local result = {}
  for i = 1, #points do
    result[i] = points[i]
  end
  return result
end

--- Moves every vertex of points by (dx, dy), in place; returns points.
function ui.move(points, dx, dy)
  for i = 1, #points, 2 do
    points[i], points[i + 1] = points[i] + dx, points[i + 1] + dy
  end
  return points
end

--- Returns a copy of points moved by (dx, dy).
function ui.translated(points, dx, dy)
  return ui.move(ui.copy(points), dx, dy)
end

--- Whether (x, y) is within radius of (cx, cy): a press on a round handle.
function ui.within(x, y, cx, cy, radius)
  local dx, dy = x - cx, y - cy
  return dx * dx + dy * dy <= radius * radius
end

--- Fills any polygon, concave or self-intersecting, with the even-odd rule.
-- love.graphics.polygon("fill") draws a triangle fan, which is only right for convex shapes.
-- Inverting the stencil once per fan triangle leaves the pixels covered an odd number of times.
function ui.fillPolygon(points, color, alpha)
  if #points < 6 then
    return
  end
  love.graphics.stencil(function()
    love.graphics.polygon("fill", points)
  end, "invert", 0)
  love.graphics.setStencilTest("notequal", 0)
  setColor(color, alpha)
  love.graphics.rectangle("fill", 0, 0, ui.WIDTH, ui.HEIGHT)
  love.graphics.setStencilTest()
end

function ui.outlinePolygon(points, color, alpha, width)
  if #points < 4 then
    return
  end
  setColor(color, alpha)
  love.graphics.setLineWidth(width or 2)
  love.graphics.polygon("line", points)
end

function ui.drawPolygon(points, color, fillAlpha)
  ui.fillPolygon(points, color, fillAlpha or 0.35)
  ui.outlinePolygon(points, color, 1, 2)
end

function ui.dot(x, y, color, radius)
  setColor(color)
  love.graphics.circle("fill", x, y, radius or 5)
end

--- A line from (x1, y1) to (x2, y2) with a head at (x2, y2); nothing for a zero vector.
function ui.arrow(x1, y1, x2, y2, color, width)
  local vx, vy = x2 - x1, y2 - y1
  local length = math.sqrt(vx * vx + vy * vy)
  if length == 0 then
    return
  end
  setColor(color)
  love.graphics.setLineWidth(width or 3)
  love.graphics.line(x1, y1, x2, y2)
  local head = math.min(12, length * 0.5)
  local ux, uy = vx / length, vy / length
  local bx, by = x2 - ux * head, y2 - uy * head
  love.graphics.polygon("fill", x2, y2, bx - uy * head * 0.45, by + ux * head * 0.45,
    bx + uy * head * 0.45, by - ux * head * 0.45)
end

--- Text with a dark box behind it; lines is a list of strings or {color, string} pairs.
function ui.panel(lines, x, y)
  local font = fonts.normal
  love.graphics.setFont(font)
  local width, lineHeight = 0, font:getHeight() + 3
  for _, line in ipairs(lines) do
    local text = type(line) == "table" and line[2] or line
    width = math.max(width, font:getWidth(text))
  end
  setColor(ui.colors.panel)
  love.graphics.rectangle("fill", x - 8, y - 6, width + 16, #lines * lineHeight + 9, 6, 6)
  for i, line in ipairs(lines) do
    local color, text = ui.colors.text, line
    if type(line) == "table" then
      color, text = line[1], line[2]
    end
    setColor(color)
    love.graphics.print(text, x, y + (i - 1) * lineHeight)
  end
end

function ui.label(text, x, y, color, size)
  love.graphics.setFont(fonts[size or "small"])
  setColor(color or ui.colors.text)
  love.graphics.print(text, x, y)
end

-- Distance from (px, py) to the segment (x1, y1)-(x2, y2), only to pick the edge under the mouse.
local function segmentDistance(px, py, x1, y1, x2, y2)
  local vx, vy = x2 - x1, y2 - y1
  local lengthSquared = vx * vx + vy * vy
  local t = 0
  if lengthSquared > 0 then
    t = math.max(0, math.min(1, ((px - x1) * vx + (py - y1) * vy) / lengthSquared))
  end
  local dx, dy = x1 + t * vx - px, y1 + t * vy - py
  return math.sqrt(dx * dx + dy * dy)
end

-- Distance from (px, py) to vertex i of points.
local function vertexDistance(px, py, points, i)
  local dx, dy = points[i] - px, points[i + 1] - py
  return math.sqrt(dx * dx + dy * dy)
end

-- Distance from (px, py) to the edge that starts at vertex i of points.
local function edgeDistance(px, py, points, i)
  local j = i + 2 > #points and 1 or i + 2
  return segmentDistance(px, py, points[i], points[i + 1], points[j], points[j + 1])
end

-- The grab { kind = kind, index = i } of the vertex or edge i nearest to (x, y) by distance(x, y,
-- points, i), if one is within radius; else nil.
local function nearest(points, x, y, kind, radius, distance)
  local best, bestDistance = nil, radius
  for i = 1, #points, 2 do
    local d = distance(x, y, points, i)
    if d <= bestDistance then
      best, bestDistance = { kind = kind, index = i }, d
    end
  end
  return best
end

--- What the mouse at (x, y) grabs of points: { kind = "vertex" | "edge" | "body", index = i }
-- (index of the vertex's x, or of the edge's first vertex), or nil. Vertices win over edges,
-- edges over the body; the body test is polygon.lua's own polygonContains.
function ui.pick(polygon, points, x, y)
  local grab = nearest(points, x, y, "vertex", ui.GRAB_RADIUS, vertexDistance)
    or nearest(points, x, y, "edge", ui.GRAB_RADIUS * 0.7, edgeDistance)
  if grab then
    return grab
  end
  if polygon.polygonContains(points, x, y) then
    return { kind = "body" }
  end
  return nil
end

--- The vertex the mouse at (x, y) grabs of points, as ui.pick gives it, or nil.
function ui.pickVertex(points, x, y)
  return nearest(points, x, y, "vertex", ui.GRAB_RADIUS, vertexDistance)
end

--- Moves the grabbed part of points (in place) by (dx, dy).
-- What a press at (x, y) grabs among several shapes, the last drawn (topmost) first:
-- the grab and the shape's index, or nil.
function ui.pickTopmost(polygon, shapes, x, y)
  for index = #shapes, 1, -1 do
    local grab = ui.pick(polygon, shapes[index], x, y)
    if grab then return grab, index end
  end
end

function ui.drag(points, grab, dx, dy)
  if grab.kind == "vertex" then
    points[grab.index] = points[grab.index] + dx
    points[grab.index + 1] = points[grab.index + 1] + dy
  elseif grab.kind == "edge" then
    local i = grab.index
    local j = i + 2 > #points and 1 or i + 2
    points[i], points[i + 1] = points[i] + dx, points[i + 1] + dy
    points[j], points[j + 1] = points[j] + dx, points[j + 1] + dy
  else
    ui.move(points, dx, dy)
  end
end

--- Highlights the grabbed handle.
function ui.drawGrab(points, grab)
  if not grab then
    return
  end
  setColor(ui.colors.yellow)
  if grab.kind == "vertex" then
    love.graphics.setLineWidth(2)
    love.graphics.circle("line", points[grab.index], points[grab.index + 1], ui.GRAB_RADIUS)
  elseif grab.kind == "edge" then
    local i = grab.index
    local j = i + 2 > #points and 1 or i + 2
    love.graphics.setLineWidth(4)
    love.graphics.line(points[i], points[i + 1], points[j], points[j + 1])
  else
    ui.outlinePolygon(points, ui.colors.yellow, 1, 3)
  end
end

function ui.vertices(points, color, radius)
  for i = 1, #points, 2 do
    ui.dot(points[i], points[i + 1], color, radius or 4)
  end
end

return ui
