-- The benchmarks' dealings with the shell: commands run, their output read, a temporary folder.
local shell = {}

-- Whether a command ran and exited 0 (os.execute's result on Lua 5.1 and on later ones).
function shell.ok(command)
  local done = os.execute(command)
  return done == true or done == 0
end

-- Whether a program is on the PATH.
function shell.have(program)
  return shell.ok("command -v " .. program .. " >/dev/null 2>&1")
end

-- A command's output, split into words.
function shell.words(command)
  local pipe = assert(io.popen(command))
  local words = {}
  for word in pipe:read("*a"):gmatch("%S+") do words[#words + 1] = word end
  pipe:close()
  return words
end

-- The earcut module file for the benchmarks' earcut columns (EARCUT, else the copy that
-- `npm install --prefix /tmp/earcut earcut` makes), when it and node are there; else nil, and
-- the line saying that those columns are skipped is printed.
function shell.earcut()
  local file = os.getenv("EARCUT") or "/tmp/earcut/node_modules/earcut/src/earcut.js"
  local found = io.open(file)
  if found then found:close() end
  if found and shell.have("node") then return file end
  print("(earcut skipped: needs node and `npm install --prefix /tmp/earcut earcut`, or EARCUT=file)")
  return nil
end

-- A new empty folder's path (remove it with shell.ok("rm -rf " .. path)).
function shell.tempDir()
  local dir = os.tmpname()
  os.remove(dir)
  assert(shell.ok("mkdir -p " .. dir))
  return dir
end

return shell
