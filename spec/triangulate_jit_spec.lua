-- LuaJIT only: the triangulator starts in the interpreter and is compiled once the
-- triangulations have spent 50 ms of CPU time interpreted (polygon/triangulate.lua). Run in a
-- fresh process, since this busted run has long since spent that budget.
local interpreter = require "interpreter"

local SCRIPT = [[
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local shapes, prng = require "shapes", require "prng"
local jutil = require "jit.util"
local traces = 0
jit.attach(function(what, _, func)
  if what == "stop" then
    local source = jutil.funcinfo(func).source or ""
    if source:match("triangulate%.lua$") or source:match("sweep%.lua$") then traces = traces + 1 end
  end
end, "trace")
local circle = shapes.noisyCircle(300, prng.new(7))
assert(#polygon.polygonTriangulate(circle) == 298)
local before = traces
local start = os.clock()
while os.clock() - start < 0.5 do assert(#polygon.polygonTriangulate(circle) == 298) end
print(before, traces)
]]

describe("polygonTriangulate on LuaJIT", function()
  if not rawget(_G, "jit") then
    it("is a LuaJIT matter (this interpreter is not LuaJIT)", function()
      assert.is_nil(rawget(_G, "jit"))
    end)
    return
  end

  it("runs its first calls interpreted and is compiled once they have taken 50 ms", function()
    local path = os.tmpname()
    local file = assert(io.open(path, "w"))
    file:write(SCRIPT)
    file:close()
    local pipe = assert(io.popen(assert(interpreter()) .. " " .. path .. " 2>&1"))
    local out = pipe:read("*a")
    pipe:close()
    os.remove(path)
    local before, after = out:match("^(%d+)%s+(%d+)")
    assert.is_truthy(before, out)
    -- one triangulation of 300 vertices takes about 3 ms interpreted: no trace of the
    -- triangulator's own yet; half a second of them crosses the budget and compiles
    assert.are.equal(0, tonumber(before))
    assert.is_true(tonumber(after) > 0, out)
  end)
end)
