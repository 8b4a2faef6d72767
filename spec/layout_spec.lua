-- The library's form: polygon.lua is a front that re-exports polygon/'s functions unwrapped, the
-- whole library works vendored under any prefix, leaks no global, and the rockspec installs
-- every file of polygon/.
local polygon = require "polygon"

-- The names of the files in polygon/, from the rockspec's module list checked below and from
-- the directory itself (through ls: plain Lua cannot list a directory).
local function libraryFiles()
  local names = {}
  local pipe = assert(io.popen("ls polygon/*.lua"))
  for line in pipe:lines() do names[#names + 1] = line:match("^polygon/([%w_]+)%.lua$") end
  pipe:close()
  table.sort(names)
  return names
end

local function readFile(path)
  local f = assert(io.open(path, "rb"))
  local text = f:read("*a")
  f:close()
  return text
end

-- the command that started this interpreter (busted's arg[-1]), as spec/examples_spec.lua finds it
local function interpreter()
  local cmd = type(arg) == "table" and arg[-1]
  assert(type(cmd) == "string" and cmd:match("^[%w%./_%-]+$"), "arg[-1] does not name the interpreter")
  return cmd
end

describe("the front, polygon.lua", function()
  it("re-exports each implementation itself, not a wrapper", function()
    -- the same function values: no extra call on a hot path, error levels at the caller's line
    local where = {
      measures = { "polygonWindingOrder", "polygonArea", "polygonAreaAccurate", "polygonType",
        "polygonCenter", "polygonCentroid" },
      contains = { "polygonContains" },
      sat = { "projectPolygon" },
      circle = { "projectCircle", "circlesCollideV" },
      collide = { "polygonCollidesWith", "polygonsCollide", "polygonCollidesWithV", "polygonsCollideV",
        "polygonCircleCollideV" },
      triangulate = { "polygonTriangulate", "polygonConvexParts" },
      transform = { "polygonBounds", "polygonTranslate", "polygonRotate" },
      object = { "validate", "Polygon" },
      rayring = { "polygonRayCast" },
      circleray = { "circleRayCast" },
      closest = { "polygonClosestPoint" },
      casts = { "polygonsCast", "circlesCast" },
      circlecast = { "polygonCircleCast" },
    }
    local count = 0
    for file, names in pairs(where) do
      local module = require("polygon." .. file)
      for _, name in ipairs(names) do
        assert.are.equal(module[name], polygon[name], name .. " in polygon/" .. file .. ".lua")
        assert.is_not_nil(polygon[name], name)
        count = count + 1
      end
    end
    -- and nothing else public: every other field of the front is metadata
    for key, value in pairs(polygon) do
      if type(value) ~= "string" then count = count - 1 end
      assert.is_true(type(value) ~= "string" or key:sub(1, 1) == "_", key)
    end
    assert.are.equal(0, count)
  end)

  it("stays short, and no file of polygon/ passes about 1,200 lines", function()
    local function lineCount(path)
      local _, n = readFile(path):gsub("\n", "")
      return n
    end
    assert.is_true(lineCount("polygon.lua") < 500)
    for _, name in ipairs(libraryFiles()) do
      local n = lineCount("polygon/" .. name .. ".lua")
      assert.is_true(n <= 1200, ("polygon/%s.lua has %d lines"):format(name, n))
    end
  end)
end)

describe("require", function()
  it("works vendored under another prefix (lib.polygon), loading nothing from elsewhere", function()
    local dir = os.tmpname()
    os.remove(dir)
    -- os.execute returns true on 5.2+, 0 on 5.1 and LuaJIT
    local status = os.execute(("mkdir -p %s/lib && cp -r polygon.lua polygon %s/lib/"):format(dir, dir))
    assert.is_true(status == true or status == 0, "copy failed")
    -- a fresh interpreter in an empty folder: only lib/ is there to be found
    local script = [[
      package.path = "./?.lua"
      local p = require "lib.polygon"
      assert(p.polygonWindingOrder({0,0, 10,0, 10,10, 0,10}) == "cw")
      assert(p.polygonsCollide({0,0, 10,0, 10,10}, {{5,1, 20,1, 20,20}}))
      for name in pairs(package.loaded) do
        assert(not name:match("^polygon"), "loaded " .. name)
      end
      io.write(package.loaded["lib.polygon.kernel"] and "vendored" or "kernel not under lib")
    ]]
    local pipe = assert(io.popen(("cd %s && %s -e '%s' 2>&1"):format(dir, interpreter(), script)))
    local out = pipe:read("*a")
    pipe:close()
    os.execute("rm -rf " .. dir)
    assert.are.equal("vendored", out)
  end)

  it("sets no global", function()
    local script = [[
      package.path = "./?.lua;" .. package.path
      local before = {}
      for k in pairs(_G) do before[k] = true end
      require "polygon"
      local added = {}
      for k in pairs(_G) do if not before[k] then added[#added + 1] = tostring(k) end end
      io.write(#added == 0 and "none" or table.concat(added, " "))
    ]]
    local pipe = assert(io.popen(("%s -e '%s' 2>&1"):format(interpreter(), script)))
    local out = pipe:read("*a")
    pipe:close()
    assert.are.equal("none", out)
  end)
end)

describe("polygon-scm-1.rockspec", function()
  it("installs the front and every file of polygon/", function()
    local rockspec = readFile("polygon-scm-1.rockspec")
    assert.is_truthy(rockspec:find('polygon = "polygon.lua"', 1, true))
    local files = libraryFiles()
    assert.is_true(#files >= 10)
    for _, name in ipairs(files) do
      local entry = ('["polygon.%s"] = "polygon/%s.lua"'):format(name, name)
      assert.is_truthy(rockspec:find(entry, 1, true), entry)
    end
    local _, listed = rockspec:gsub('%["polygon%.[%w_]+"%]', "")
    assert.are.equal(#files, listed)
  end)
end)
