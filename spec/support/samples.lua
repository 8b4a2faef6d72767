--- Small polygons (flat arrays, screen coordinates, y down) that between them take the branches
-- of the per-call functions, for the specs that run every function over the same inputs (zero
-- garbage, inputs left unchanged). Callers must not modify them.
local samples = {
  SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 },
  SQUARE_CCW = { 0, 0, 0, 10, 10, 10, 10, 0 },
  L = { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }, -- concave
  OVERLAP = { 8, 2, 18, 2, 18, 12, 8, 12 }, -- overlaps SQUARE by 2 along x
  TOUCH = { 10, 0, 20, 0, 20, 10, 10, 10 }, -- shares SQUARE's right edge
  APART = { 30, 0, 40, 0, 40, 10, 30, 10 },
  INSIDE = { 6, 3, 8, 3, 8, 5, 6, 5 }, -- inside SQUARE
  REPEATED = { 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 }, -- a vertex given twice
  CLOSED = { 0, 0, 10, 0, 10, 10, 0, 10, 0, 0 }, -- the first vertex repeated at the end
  TRIANGLE = { 5, 13, 12, 6, 15, 15 },
  SEGMENT = { 2, 5, 8, 5, 5, 5 }, -- three collinear points: zero area
  TWO = { 2, 5, 8, 5 }, -- two points
  STAR = { 10, 0, 16, 20, 0, 7, 20, 7, 4, 20 }, -- a pentagram: self-intersecting
  SLIVER = { 0, 0, 2 ^ 27 + 1, 2 ^ 27, 2 ^ 27, 2 ^ 27 - 1 }, -- area 1 between coordinates near 2^27
}

return samples
