-- The README's quoted outputs cannot go stale: every ```lua block that shows what it prints
-- (`--> text` at the end of a line) is run, and its printed lines compared with those texts in
-- order; the arena checksum the README quotes is the one examples/arena.lua prints.
local interpreter = require "interpreter"

local loadChunk = rawget(_G, "loadstring") or load   -- Lua 5.1's load takes no string

local function readme()
  local f = assert(io.open("README.md", "rb"))
  local text = f:read("*a")
  f:close()
  return text
end

-- Every ```lua block with at least one `-->`: its code, its first line in the README, and the
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

-- Runs a block with print collecting its lines.
local function run(block)
  local printed = {}
  local function collect(...)
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
    -- the README shows print's tabs as spaces: runs of white space compare as one space
    printed[#printed + 1] = table.concat(parts, "\t"):gsub("%s+", " ")
  end
  local chunk = assert(loadChunk("local print = ...\n" .. table.concat(block.code, "\n"),
    "README.md:" .. block.line))
  chunk(collect)
  return printed
end

describe("README.md", function()
  local text = readme()
  local blocks = blocksWithOutput(text)

  it("shows the output of at least the example and the concave levels", function()
    assert.is_true(#blocks >= 4)
  end)

  for _, block in ipairs(blocks) do
    it("prints what it shows in the block at line " .. block.line, function()
      assert.are.same(block.expected, run(block))
    end)
  end

  it("quotes the checksum examples/arena.lua prints after 300 frames", function()
    local quoted = text:match("examples/arena.lua 300` ends with `checksum ([%d%.]+)`")
    assert.is_string(quoted)
    local pipe = assert(io.popen(assert(interpreter()) .. " examples/arena.lua 300 2>&1"))
    local out = pipe:read("*a")
    pipe:close()
    assert.are.equal(quoted, out:match("checksum%s+([%d%.]+)"))
  end)
end)
