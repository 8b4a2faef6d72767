-- The quoted outputs of the README and of the docs pages its examples moved to cannot go stale:
-- every ```lua block that shows what it prints (`--> text` at the end of a line) is run, and its
-- printed lines compared with those texts in order; the arena checksum the README quotes is the
-- one examples/arena.lua prints.
local interpreter = require "interpreter"

local loadChunk = rawget(_G, "loadstring") or load   -- Lua 5.1's load takes no string

-- Each page whose examples are run, and how many blocks with output it holds at least (so that a
-- page whose blocks the parser stopped finding fails).
local PAGES = {
  { file = "README.md", least = 3 },           -- the example, the U floor, the game loop
  { file = "docs/reference.md", least = 3 },   -- polygonRayCast, polygonClosestPoint, polygonsCast
  { file = "docs/levels.md", least = 4 },      -- a room, caves, what is refused, a tile map
  { file = "docs/arena.md", least = 1 },       -- a swept move
}

local function read(file)
  local f = assert(io.open(file, "rb"))
  local text = f:read("*a")
  f:close()
  return text
end

-- Every ```lua block with at least one `-->`: its code, its first line in the page, and the
-- texts after `-->`, one per line that has one.
local function blocksWithOutput(text)
  local blocks, lineNo, inBlock, current = {}, 0, false, nil
  for line in (text .. "\n"):gmatch("([^\n]*)\n") do
    lineNo = lineNo + 1
    if not inBlock and line == "```lua" then
      inBlock, current = true, { code = {}, expected = {}, line = lineNo + 1 }
    elseif inBlock and line == "```" then
      inBlock = false
      if #current.expected > 0 then blocks[#blocks + 1] = current end
    elseif inBlock then
      current.code[#current.code + 1] = line
      local shown = line:match("%-%->%s*(.-)%s*$")
      if shown then current.expected[#current.expected + 1] = shown:gsub("%s+", " ") end
    end
  end
  return blocks
end

-- Runs a block of a page with print collecting its lines.
local function run(file, block)
  local printed = {}
  local function collect(...)
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
    -- the README shows print's tabs as spaces: runs of white space compare as one space
    printed[#printed + 1] = table.concat(parts, "\t"):gsub("%s+", " ")
  end
  local chunk = assert(loadChunk("local print = ...\n" .. table.concat(block.code, "\n"),
    file .. ":" .. block.line))
  chunk(collect)
  return printed
end

for _, page in ipairs(PAGES) do
  describe(page.file, function()
    local blocks = blocksWithOutput(read(page.file))

    it("shows the output of at least " .. page.least .. " examples", function()
      assert.is_true(#blocks >= page.least)
    end)

    for _, block in ipairs(blocks) do
      it("prints what it shows in the block at line " .. block.line, function()
        assert.are.same(block.expected, run(page.file, block))
      end)
    end
  end)
end

describe("README.md", function()
  local text = read("README.md")

  it("quotes the checksum examples/arena.lua prints after 300 frames", function()
    local quoted = text:match("examples/arena.lua 300` ends with `checksum ([%d%.]+)`")
    assert.is_string(quoted)
    local pipe = assert(io.popen(assert(interpreter()) .. " examples/arena.lua 300 2>&1"))
    local out = pipe:read("*a")
    pipe:close()
    assert.are.equal(quoted, out:match("checksum%s+([%d%.]+)"))
  end)
end)
