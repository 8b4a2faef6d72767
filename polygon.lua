local polygon = {
  _VERSION     = "polygon 0.7.0",
  _DESCRIPTION = "Polygon geometry for games: winding, area, convexity, centre, point in polygon, "
              .. "separating-axis collision with a minimum translation vector, polygon against circle",
  _URL         = "https://github.com/polygon-lua/polygon.lua",
  _LICENSE     = [[
    MIT License

    Copyright (c) 2026 the polygon.lua developers

    Permission is hereby granted, free of charge, to any person obtaining a copy of this software
    and associated documentation files (the "Software"), to deal in the Software without
    restriction, including without limitation the rights to use, copy, modify, merge, publish,
    distribute, sublicense, and/or sell copies of the Software, and to permit persons to whom the
    Software is furnished to do so, subject to the following conditions:

    The above copyright notice and this permission notice shall be included in all copies or
    substantial portions of the Software.

    THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED, INCLUDING
    BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE AND
    NONINFRINGEMENT. IN NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM,
    DAMAGES OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
    OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
  ]],
}

local _PACKAGE = ... .. "."
local measures = require(_PACKAGE .. "measures")
local contains = require(_PACKAGE .. "contains")
local sat = require(_PACKAGE .. "sat")
local circle = require(_PACKAGE .. "circle")
local collide = require(_PACKAGE .. "collide")
local triangulate = require(_PACKAGE .. "triangulate")
local transform = require(_PACKAGE .. "transform")
local object = require(_PACKAGE .. "object")

polygon.polygonWindingOrder = measures.polygonWindingOrder
polygon.polygonArea = measures.polygonArea
polygon.polygonAreaAccurate = measures.polygonAreaAccurate
polygon.polygonType = measures.polygonType
polygon.polygonCenter = measures.polygonCenter
polygon.polygonCentroid = measures.polygonCentroid
polygon.polygonContains = contains.polygonContains
polygon.projectPolygon = sat.projectPolygon
polygon.polygonCollidesWith = collide.polygonCollidesWith
polygon.polygonsCollide = collide.polygonsCollide
polygon.polygonCollidesWithV = collide.polygonCollidesWithV
polygon.polygonsCollideV = collide.polygonsCollideV
polygon.projectCircle = circle.projectCircle
polygon.circlesCollideV = circle.circlesCollideV
polygon.polygonCircleCollideV = collide.polygonCircleCollideV
polygon.polygonTriangulate = triangulate.polygonTriangulate
polygon.polygonConvexParts = triangulate.polygonConvexParts
polygon.polygonBounds = transform.polygonBounds
polygon.polygonTranslate = transform.polygonTranslate
polygon.polygonRotate = transform.polygonRotate
polygon.validate = object.validate
polygon.Polygon = object.Polygon

return polygon
