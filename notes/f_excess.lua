-- How much longer polygonsCollideV's push on compound shapes is than the true least translation
-- (spec/support/union.lua), on random clusters, terrains and crates at offsets 0 to 1e12.
-- Run from the worktree root: lua5.4 notes/f_excess.lua SEED TRIALS
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local union, parts, scenes, prng = require "union", require "parts", require "scenes", require "prng"
local g = prng.new(tonumber(arg[1]) or 11)
local stats = { n = 0, over = 0, worst = 0, worstRel = 0, fail = 0, under = 0 }
local byOff = {}
local curOff
local function run(s1, s2)
  local o, dx, dy = polygon.polygonsCollideV(s1, s2)
  local truth = parts.collide(s1, s2)
  assert(truth == (o ~= false), "boolean")
  if not o then return end
  stats.n = stats.n + 1
  if parts.collide(s1, parts.translate(s2, dx, dy)) then stats.fail = stats.fail + 1 end
  local d = union.leastTranslation(s1, s2)
  local ex = o - d
  local slack = parts.slack(s1, s2)
  if ex > slack then stats.over = stats.over + 1 end
  if ex < -1e-9 * (1 + d) then stats.under = stats.under + 1 end
  stats.worst = math.max(stats.worst, ex)
  local b = byOff[curOff] or { n = 0, over = 0, worst = 0, exceed = 0 }
  byOff[curOff] = b
  b.n = b.n + 1
  if ex > 1e-12 * (1 + d) then b.exceed = b.exceed + 1 end
  if ex > slack then b.over = b.over + 1 end
  b.worst = math.max(b.worst, ex)
  stats.worstRel = math.max(stats.worstRel, ex / d)
end
for _ = 1, tonumber(arg[2]) or 300 do
  local kind = g:int(1, 3)
  local off = ({ 0, 1e5, 1e9, 1e12 + 0.375 })[g:int(1, 4)]
  local s1, s2
  if kind == 1 then
    s1, s2 = scenes.cluster(g, g:int(1, 5), 60, 30), scenes.cluster(g, g:int(1, 2), 60, 20)
  elseif kind == 2 then
    local w
    s1, w = scenes.terrain(g, 12)
    local x, y = g:range(0, w - 10), g:range(10, 80)
    s2 = { { x, y, x + 10, y, x + 10, y + 10, x, y + 10 } }
  else
    s1 = scenes.terrain(g, 8)
    s2 = scenes.cluster(g, 2, 60, 10)
  end
  curOff = off
  s1, s2 = parts.translate(s1, off, off), parts.translate(s2, off, off)
  run(s1, s2)
  run(s2, s1)
end
print(("collisions %d  over slack %d  shorter than oracle %d  not separated %d  worst excess %.3g"
  .. "  worst rel %.3g")
  :format(stats.n, stats.over, stats.under, stats.fail, stats.worst, stats.worstRel))
for _, off in ipairs({ 0, 1e5, 1e9, 1e12 + 0.375 }) do
  local b = byOff[off]
  print(("offset %-8.3g collisions %4d  longer than the least translation by > 1e-12 (1 + d): %4d"
    .. "  beyond 3x the face margin: %3d  largest excess %.3g"):format(off, b.n, b.exceed, b.over, b.worst))
end
