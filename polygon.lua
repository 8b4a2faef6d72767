-- polygon.lua, the front door: its metadata, then every public function in the order of the README.
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

--- Polygon geometry for games, in pure Lua (5.1 to 5.4, LuaJIT, LÖVE).
--
-- Points are flat arrays `{x1, y1, x2, y2, ...}` in screen coordinates: y grows downwards, as in
-- LÖVE, so "cw" is clockwise as seen on screen. No function modifies `points` unless it is also
-- passed as `out`. The collision functions take convex polygons of either winding, or lists of
-- convex parts (from @{polygonConvexParts}) where they say so, and check it on every call: a
-- concave polygon, fewer than 3 points or point tables raise. Touching is not colliding; no
-- collision is `false` alone. A `Polygon` object is taken wherever a polygon is, for its points.
--
-- An argument error names the function, the argument and what it got, at the caller's line:
-- `polygonArea: points must be a table, got nil`. Below, eps is 2^-53 and M the largest
-- coordinate magnitude involved. The error analysis behind each bound is in docs/accuracy.md.
--
-- This file is the front: the implementations live in `polygon/`, one concept a file, and each
-- export below names the file that holds its function.
-- @module polygon

local _PACKAGE = ... .. "."   -- "polygon." or, from a game's lib folder, "lib.polygon."
local measures    = require(_PACKAGE .. "measures")
local contains    = require(_PACKAGE .. "contains")
local sat         = require(_PACKAGE .. "sat")
local collide     = require(_PACKAGE .. "collide")
local circle      = require(_PACKAGE .. "circle")
local triangulate = require(_PACKAGE .. "triangulate")
local transform   = require(_PACKAGE .. "transform")
local object      = require(_PACKAGE .. "object")
local rayring     = require(_PACKAGE .. "rayring")
local circleray   = require(_PACKAGE .. "circleray")
local closest     = require(_PACKAGE .. "closest")
local casts       = require(_PACKAGE .. "casts")
local circlecast  = require(_PACKAGE .. "circlecast")

--- Measures
-- @section measures

--- The winding order as seen on screen (y down): `{0,0, 10,0, 10,10, 0,10}` is `"cw"`. Exact.
-- @function polygonWindingOrder
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`
-- @treturn ?string `"cw"` or `"ccw"`; nil for fewer than 3 points or a signed area of exactly 0
-- @raise when points is not a table of an even number of coordinates, or holds NaN or an infinity
polygon.polygonWindingOrder = measures.polygonWindingOrder

--- The area by the shoelace formula relative to the first vertex: a few ulps off wherever the
-- polygon lies. A self-intersecting polygon's lobes count with their winding's sign; an area
-- beyond the largest double is `inf`.
-- @function polygonArea
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`
-- @treturn ?number the area, not negative; nil for fewer than 3 points
-- @raise as @{polygonWindingOrder}
polygon.polygonArea = measures.polygonArea

--- The exact area of the given doubles, rounded to within one ulp. Slower than @{polygonArea}:
-- an error-free split first, a compensated sum where its test fails, an exact sum where that
-- cannot vouch for the result.
-- @function polygonAreaAccurate
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`
-- @treturn ?number the area, not negative; nil for fewer than 3 points
-- @raise as @{polygonWindingOrder}
polygon.polygonAreaAccurate = measures.polygonAreaAccurate

--- Whether the polygon is convex, checking every vertex. Repeated vertices and collinear ones
-- that go on forward keep it convex; a spike that doubles back, a self-intersection or winding
-- round more than once make it concave. Exact.
-- @function polygonType
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`
-- @treturn ?string `"convex"` or `"concave"`; nil for fewer than 3 points or all on one line
-- @raise as @{polygonWindingOrder}, once a non-finite coordinate is read (two certain turns of
-- opposite sign before it answer `"concave"`)
polygon.polygonType = measures.polygonType

--- The centre as the tutorial defines it: the mean of the vertices, within an ulp or two of
-- exact wherever the polygon lies and whatever its size.
-- @function polygonCenter
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`
-- @treturn ?number cx; nil for fewer than 3 points
-- @treturn number cy
-- @raise as @{polygonWindingOrder}
polygon.polygonCenter = measures.polygonCenter

--- The area centroid, the point a physics step turns a uniform body about: within a few ulps of
-- M of the exact centroid, slivers and nearly degenerate polygons included.
-- @function polygonCentroid
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`
-- @treturn ?number cx; nil for fewer than 3 points or an area of exactly 0
-- @treturn number cy
-- @raise as @{polygonWindingOrder}
polygon.polygonCentroid = measures.polygonCentroid

--- Point in polygon
-- @section contains

--- Whether (x, y) lies inside, by the tutorial's crossing rule (a ray to the right). Works for
-- concave and self-intersecting polygons (even-odd). Exact. The boundary is half-open: of two
-- polygons sharing an edge, at most one contains a point of it.
-- @function polygonContains
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`, not scanned (see @{validate})
-- @number x
-- @number y
-- @treturn boolean false also for fewer than 3 points
-- @raise when points is not a table of an even number of coordinates, or x or y is not a finite
-- number
polygon.polygonContains = contains.polygonContains

--- Separating axes
-- @section sat

--- The range of the polygon projected on the axis (nx, ny), relative to the point (x, y).
-- @function projectPolygon
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`
-- @number x
-- @number y
-- @number nx
-- @number ny
-- @treturn ?number min of `(px - x) * nx + (py - y) * ny` over the vertices; nil for no points
-- @treturn number max
-- @raise when points is not a table of an even number of coordinates, or x, y, nx or ny is not
-- a number
polygon.projectPolygon = sat.projectPolygon

--- Whether no edge normal of `points1` separates two convex polygons (the tutorial's one-sided
-- test). Touching is not colliding; zero area never collides. Exact. Convex polygons of 3 or
-- more points only, no lists of parts (checked exactly on every call).
-- @function polygonCollidesWith
-- @tparam table points1 flat array `{x1, y1, x2, y2, ...}`
-- @tparam table points2 flat array
-- @treturn boolean
-- @raise when either is not a table of an even number of coordinates, holds NaN or an
-- infinity, is not convex (`points1 is not convex (a reflex turn at vertex 4); split it once
-- with polygonConvexParts and pass the parts`), has fewer than 3 points or holds point tables
polygon.polygonCollidesWith = collide.polygonCollidesWith

--- Whether two convex polygons overlap, by the separating axis theorem. Touching is not
-- colliding; zero area never collides. Exact.
-- @function polygonsCollide
-- @tparam table points1 flat array, or a list of convex parts (colliding when any part does)
-- @tparam table points2 the same
-- @treturn boolean
-- @raise as @{polygonCollidesWith}, naming the part of a list
polygon.polygonsCollide = collide.polygonsCollide

--- As @{polygonsCollideV}, over the axes of `points1` only: after the push,
-- `polygonCollidesWith(points1, moved)` is false. Convex polygons only.
-- @function polygonCollidesWithV
-- @tparam table points1 flat array `{x1, y1, x2, y2, ...}`
-- @tparam table points2 flat array, the polygon the push moves
-- @treturn number|boolean overlap, or false when they do not collide
-- @treturn number dx
-- @treturn number dy
-- @raise as @{polygonCollidesWith}
polygon.polygonCollidesWithV = collide.polygonCollidesWithV

--- As @{polygonsCollide}, with the minimum translation vector: (dx, dy) moves `points2` out of
-- `points1` (subtract it from `points1` to move that one instead), right in either argument
-- order and when the centres coincide. One push separates: after adding it to every vertex of
-- `points2`, rounded as a game adds it, @{polygonsCollide} says false. The push is at most 8 eps M
-- longer than the exact depth (lists of parts: see the README).
-- @function polygonsCollideV
-- @tparam table points1 flat array, or a list of convex parts
-- @tparam table points2 the same, the shape the push moves (never along a seam between parts)
-- @treturn number|boolean overlap, the push's length; or false, exactly where @{polygonsCollide}
-- gives false
-- @treturn number dx
-- @treturn number dy
-- @raise as @{polygonsCollide}
polygon.polygonsCollideV = collide.polygonsCollideV

--- Circles
-- @section circle

--- The range of a circle projected on the axis (nx, ny) of unit length, relative to (x, y).
-- @function projectCircle
-- @number cx
-- @number cy
-- @number radius
-- @number x
-- @number y
-- @number nx
-- @number ny
-- @treturn number min, the centre's projection minus radius
-- @treturn number max, plus radius
-- @raise when an argument is not a number or the radius is negative
polygon.projectCircle = circle.projectCircle

--- Whether two circles overlap, with the push that separates them, moving the second circle.
-- Exact: they collide when `(x2 - x1)^2 + (y2 - y1)^2 < (r1 + r2)^2` for the given doubles, so
-- touching is not colliding and a circle of radius 0 collides only strictly inside the other.
-- After `x2 + dx, y2 + dy` (rounded) they no longer collide; the push is at most 8 eps M longer
-- than the overlap (M the centres before and after). Equal centres are pushed along +x.
-- Allocates nothing.
-- @function circlesCollideV
-- @number x1
-- @number y1
-- @number r1
-- @number x2
-- @number y2
-- @number r2
-- @treturn number|boolean overlap = r1 + r2 - distance, or false
-- @treturn number dx
-- @treturn number dy
-- @raise when an argument is not a finite number or a radius is negative
polygon.circlesCollideV = circle.circlesCollideV

--- The push of a circle out of a convex polygon (either winding) or a list of convex parts.
-- Collides exactly when the open disc meets the polygon's interior: touching is not colliding,
-- a radius of 0 or zero area never collide. The overlap is the full
-- penetration, so a circle deep inside leaves in one step; after `cx + dx, cy + dy` (rounded) it
-- no longer collides, and the push is at most 8 eps M longer than the exact depth (M over the
-- polygon, the centre and the moved centre, not the radius).
-- @function polygonCircleCollideV
-- @tparam table points flat array, or a list of convex parts
-- @number cx
-- @number cy
-- @number radius
-- @treturn number|boolean overlap, or false
-- @treturn number dx, moving the circle (subtract it from the polygon to move that instead)
-- @treturn number dy
-- @raise when points is not a table of an even number of coordinates, holds NaN or an
-- infinity, is not convex, has fewer than 3 points or holds point tables, or cx, cy or radius
-- is not a finite number, or the radius is negative
polygon.polygonCircleCollideV = collide.polygonCircleCollideV

--- Rays
-- @section raycast

--- Where the segment from (x1, y1) to (x2, y2) first enters the open interior of a polygon of
-- any shape (convex or concave, either winding, self-intersecting: its interior by the crossing
-- rule, even-odd, as @{polygonContains}, without the boundary) or of the union of a list of
-- convex parts: line of sight, hitscan, ground probes; a concave level outline needs no split.
-- Touching is not colliding (grazing a vertex or running along an edge is a miss), and a seam
-- between parts never stops a ray: one along a seam enters where the seam meets the outline.
-- The hit or miss and the edge are exact; the point at `fraction` lies within 8 eps M of the
-- exact entry point (M over the segment's ends). Allocates nothing (the exact path's scratch
-- grows once, to the largest polygon it meets).
-- @function polygonRayCast
-- @tparam table points flat array of 3 or more points, or a list of convex parts
-- @number x1
-- @number y1
-- @number x2
-- @number y2
-- @treturn number|boolean fraction t in [0, 1], the entry at (x1 + t (x2 - x1), y1 + t (y2 -
-- y1)); 0 when the segment starts strictly inside (then nx, ny are 0 too); or false
-- @treturn number nx, the unit outward normal of the outline's edge entered (at a vertex,
-- either edge's)
-- @treturn number ny
-- @raise as @{polygonCircleCollideV} for points, save that a flat polygon need not be convex
-- and only its first entry's type is checked, as in @{polygonContains} (a list's parts must be
-- convex; a segment is refused: it is not a polygon), and when x1, y1, x2 or y2 is not a finite
-- number
polygon.polygonRayCast = rayring.polygonRayCast

--- As @{polygonRayCast}, against the open disc: a tangent ray is a miss. The normal is
-- (P(fraction) - centre) / radius, within a few ulps. Allocates nothing.
-- @function circleRayCast
-- @number cx
-- @number cy
-- @number radius
-- @number x1
-- @number y1
-- @number x2
-- @number y2
-- @treturn number|boolean fraction, or false (always for radius 0)
-- @treturn number nx
-- @treturn number ny
-- @raise when an argument is not a finite number or the radius is negative
polygon.circleRayCast = circleray.circleRayCast

--- Where a convex polygon moving by t (dx, dy), t in [0, 1], first touches a static convex
-- polygon or list of convex parts: a swept move, so that a fast body never passes through a
-- thin wall between two frames. They collide at t when their open interiors meet (sliding along
-- a face or grazing a corner is a miss; passing through a thin wall within one move is a hit);
-- the hit or miss is exact. The fraction is stepped back from the exact contact time so that
-- moving points2 by fraction * (dx, dy) the way a game does (each coordinate x + fraction * dx,
-- rounded) leaves the pair not colliding by @{polygonsCollide}, and it is no earlier than the
-- exact contact time less 8 eps M / |(dx, dy)| (eps = 2^-53, M the largest coordinate magnitude
-- involved, moved positions included), save where the motion grazes the contact so closely that
-- every fraction in that window leaves the rounded shapes colliding: then the latest one found
-- that does not. Allocates nothing.
-- @function polygonsCast
-- @tparam table points1 the static shape: flat array, or a list of convex parts
-- @tparam table points2 the moving convex polygon, flat array
-- @number dx the move
-- @number dy
-- @treturn number|boolean fraction in [0, 1]; 0 when the pair already collides at t = 0; or
-- false (also for no move, unless already colliding)
-- @treturn number nx, the unit contact normal from points1 toward points2 (it opposes the
-- motion); when already colliding, the direction of @{polygonsCollideV}'s push
-- @treturn number ny
-- @raise as @{polygonsCollideV} for points1 and points2 (a segment too: cast it with
-- @{polygonRayCast}; points2 a list of parts too), and when dx or dy is not a finite number
polygon.polygonsCast = casts.polygonsCast

--- As @{polygonsCast}, for a moving circle (x2, y2, r2) against a static circle (x1, y1, r1): the
-- disc of radius r1 + r2 (its rounding never changes a decision) met by the moving centre. A
-- tangent pass is a miss. The same contract for the fraction (M over the centres, the moved
-- centre included). Allocates nothing.
-- @function circlesCast
-- @number x1 the static circle
-- @number y1
-- @number r1
-- @number x2 the moving circle
-- @number y2
-- @number r2
-- @number dx the move
-- @number dy
-- @treturn number|boolean fraction; 0 when already colliding; or false
-- @treturn number nx, the unit normal from the static centre toward the moving one at contact
-- (when already colliding, the direction of @{circlesCollideV}'s push)
-- @treturn number ny
-- @raise when an argument is not a finite number or a radius is negative
polygon.circlesCast = casts.circlesCast

--- As @{polygonsCast}, for a moving circle (centre (cx, cy), its radius) against a static convex
-- polygon or list of convex parts: they collide at t when the open disc meets the shape's open
-- interior, the centre within the radius of the shape (sliding along a face or grazing a corner
-- at exactly the radius is a miss; passing through a thin wall within one move is a hit), and a
-- seam between parts is never met. The hit or miss is exact. The same contract for the fraction
-- (the moved centre, each coordinate rounded, leaves @{polygonCircleCollideV} false; no earlier
-- than the exact contact less 8 eps M / |(dx, dy)|, M over the shape and the centre moved or
-- not, with the same exception where the motion grazes the contact). Allocates nothing.
-- @function polygonCircleCast
-- @tparam table points the static shape: flat array, or a list of convex parts
-- @number cx the moving circle's centre
-- @number cy
-- @number radius
-- @number dx the move
-- @number dy
-- @treturn number|boolean fraction in [0, 1]; 0 when already colliding; or false (also for no
-- move, unless already colliding, and always for radius 0)
-- @treturn number nx, the unit contact normal from the shape toward the circle: a face's
-- outward normal, or from the corner toward the centre at contact (when already colliding, the
-- direction of @{polygonCircleCollideV}'s push)
-- @treturn number ny
-- @raise as @{polygonsCast} for points, and when cx, cy, radius, dx or dy is not a finite
-- number or the radius is negative
polygon.polygonCircleCast = circlecast.polygonCircleCast

--- The nearest point of the polygon's boundary to (x, y), and the signed distance to it: AI
-- sensing, snapping, aim assist. Any polygon, convex or not (a self-intersecting one too: its
-- edges are the boundary). The point and the distance are within 8 eps M of exact (M over the
-- polygon and the point); the sign is exact. Allocates nothing.
-- @function polygonClosestPoint
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`, at least one point
-- @number x
-- @number y
-- @treturn number px, the nearest point of the boundary
-- @treturn number py
-- @treturn number distance from (x, y) to it: negative when (x, y) lies inside by
-- @{polygonContains}, 0 on the boundary (then px, py is (x, y))
-- @raise when points is not a flat array of finite numbers (empty, point tables, a list of
-- parts), or x or y is not a finite number
polygon.polygonClosestPoint = closest.polygonClosestPoint

--- Concave shapes
-- @section triangulate

--- Splits a polygon, optionally with holes, into triangles. Builds new tables: for load time, not
-- for every frame. Weakly simple outlines work (repeated vertices, straight runs, an outline
-- touching itself at a vertex); every decision is an exact sign.
-- @function polygonTriangulate
-- @tparam table points flat array, either winding
-- @tparam[opt] {table,...} holes flat arrays inside the polygon, either winding; a hole may
-- touch the outline or another hole at a vertex; a hole enclosing nothing (fewer than 3
-- points, or zero area without crossing itself) is skipped; one of zero area crossing itself
-- (two edges crossing, or a figure eight whose loops cancel, touching itself) is refused
-- @treturn[1] {table,...} triangles `{x1, y1, x2, y2, x3, y3}`, copies of input vertices, each
-- wound like `points`, none of zero area; a vertex in line with its neighbours (a straight run,
-- or one left so as triangles are cut off) may be the corner of none, lying on a triangle's edge
-- (so there may be fewer than n - 2)
-- @return[2] nil
-- @treturn[2] string why: fewer than 3 points, zero area, crossing edges (a bow-tie too), the
-- rings that cross (`holes[2] crosses the outline`), a hole outside the polygon or inside
-- another hole
-- @raise when points or a hole is not an array of finite numbers
polygon.polygonTriangulate = triangulate.polygonTriangulate

--- Splits a polygon, optionally with holes, into convex parts: the triangulation merged
-- greedily (Hertel and Mehlhorn, at most four times the fewest parts). Builds new tables: for
-- load time. The list goes wherever @{polygonsCollide}, @{polygonsCollideV} and
-- @{polygonCircleCollideV} take a polygon.
-- @function polygonConvexParts
-- @tparam table points flat array, either winding
-- @tparam[opt] {table,...} holes as in @{polygonTriangulate}
-- @treturn[1] {table,...} convex flat arrays of input vertices wound like `points`, their
-- interiors disjoint, their union the polygon; one part for a convex polygon. When every edge
-- runs along an axis, axis-parallel rectangles whose corners' coordinates are input ones
-- @return[2] nil
-- @treturn[2] string why, as in @{polygonTriangulate}
-- @raise as @{polygonTriangulate}
polygon.polygonConvexParts = triangulate.polygonConvexParts

--- Moving shapes
-- @section transform

--- The axis-aligned bounding box, what a broadphase sorts shapes by. Allocates nothing.
-- Coordinates are taken as finite (@{validate} checks them): a NaN is skipped.
-- @function polygonBounds
-- @tparam table points flat array, or a list of convex parts (then the box of them all)
-- @treturn ?number minx; nil for no points
-- @treturn number miny
-- @treturn number maxx
-- @treturn number maxy
-- @raise when points (or a part) is not a table of an even number of coordinates
polygon.polygonBounds = transform.polygonBounds

--- The shape moved by (dx, dy), each coordinate rounded once (`x + dx`).
-- @function polygonTranslate
-- @tparam table points flat array, or a list of convex parts
-- @number dx
-- @number dy
-- @tparam[opt] table out the table to write into, reused each frame so that nothing is
-- allocated; may be `points` itself. Without it the result is a new table (for a list, a new
-- list of new parts): fine once, garbage every frame.
-- @treturn table out
-- @raise when points is not a flat array or a list of parts, dx or dy is not a finite number, or
-- out is given and is not a table
polygon.polygonTranslate = transform.polygonTranslate

--- The shape turned by `angle` radians about (ox, oy). On screen (y down) a positive angle turns
-- clockwise: (1, 0) about (0, 0) by pi / 2 goes to (0, 1). A vertex at distance r from the pivot
-- lands within 4 eps (r + |x'|) of the exact rotation by the rounded cosine and sine; `angle` 0
-- copies the points bit for bit. A convex polygon's vertex within rounding of its neighbours'
-- line may come out on either side (rotate a base shape by the total angle each frame).
-- @function polygonRotate
-- @tparam table points flat array, or a list of convex parts
-- @number angle
-- @number[opt] ox the pivot, both or neither; by default the area centroid (of a list, the
-- parts' centroids weighted by area; the vertex mean when there is no area)
-- @number[opt] oy
-- @tparam[opt] table out as in @{polygonTranslate}; it may also come third: (points, angle, out)
-- @treturn table out
-- @raise when points is not a flat array or a list of parts, angle (or a pivot given) is not a
-- finite number, or out is given and is not a table
polygon.polygonRotate = transform.polygonRotate

--- Checking
-- @section validate

--- Checks everything about a polygon in O(n), which the per-frame functions leave out: a table,
-- an even number of coordinates, at least 3 points, every coordinate a finite number.
-- @function validate
-- @param points anything
-- @treturn[1] boolean true
-- @return[2] nil
-- @treturn[2] string what is wrong, as `points[3] must be a finite number, got nan`
polygon.validate = object.validate

--- A polygon object wrapping a validated points table (not a copy).
-- @type Polygon

--- A new Polygon; `Polygon(points)` is the same.
-- @function Polygon.new
-- @tparam table points flat array `{x1, y1, x2, y2, ...}`, kept as the object's `points` field
-- @treturn Polygon
-- @raise @{validate}'s message, as `Polygon.new: points must hold at least 3 points, got 2`

--- Whether (x, y) lies inside, as `polygonContains(self.points, x, y)`.
-- @function Polygon:contains
-- @number x
-- @number y
-- @treturn boolean
-- @raise as @{polygonContains}, naming `Polygon:contains`
polygon.Polygon = object.Polygon

return polygon
