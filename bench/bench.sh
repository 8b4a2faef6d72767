#!/bin/sh
# bench/bench.sh: polygon.lua against the tutorial's formulas, speed beside error (make bench).
#   bash bench/bench.sh                 full run: writes bench/RESULTS.md, bench/data/<lua>.dat and,
#                                       with gnuplot, bench/speed-vs-error.png
#   BENCH_QUICK=1 bash bench/bench.sh   seconds, small inputs, output to a temporary directory (CI)
#   BENCH_LUAS="luajit" bash bench/bench.sh   the interpreters (default: luajit lua5.4 lua5.2 lua5.1)
#   luajit bench/run.lua --only "polygonType ord"   one interpreter, the rows matching a pattern
# Exits non-zero when a run fails (an error in a row, a function missing, a NaN checksum, no
# interpreter) or gnuplot fails on bench/plot.gp.
set -u
cd "$(dirname "$0")/.." || exit 2
quick=${BENCH_QUICK:-0}
luas=${BENCH_LUAS:-luajit lua5.4 lua5.2 lua5.1}
out=bench flag=
if [ "$quick" = 1 ]; then out=$(mktemp -d "${TMPDIR:-/tmp}/polygon-bench.XXXXXX") || exit 2; flag=--quick; fi
sections=$(mktemp -d "${TMPDIR:-/tmp}/polygon-bench-sections.XXXXXX") || exit 2
mkdir -p "$out/data"
# which library was measured: the last commit that changed polygon.lua or polygon/ (BENCH_REV overrides)
rev=${BENCH_REV:-$(git log -1 --format=%h -- polygon.lua polygon 2>/dev/null || echo "an unknown revision")}
if git rev-parse --git-dir >/dev/null 2>&1 && ! git diff --quiet HEAD -- polygon.lua polygon 2>/dev/null; then
  rev="$rev plus uncommitted changes to the library"
fi

status=0 ran= start=$(date +%s)
for lua in $luas; do
  if ! command -v "$lua" >/dev/null 2>&1; then echo "bench.sh: $lua not found, skipped" >&2; continue; fi
  # shellcheck disable=SC2086
  "$lua" bench/run.lua $flag --label "$lua" --out "$sections/$lua.md" --data "$out/data/$lua.dat" ||
    { echo "bench.sh: $lua bench/run.lua failed" >&2; status=1; }
  ran="$ran $lua"
done
[ -n "$ran" ] || { echo "bench.sh: no Lua interpreter found (tried: $luas)" >&2; exit 1; }

# Appends to FILE a section titled TITLE holding COMMAND's output as a code block; a failure of
# COMMAND is reported and fails the run: section FILE TITLE COMMAND...
section() {
  file=$1 title=$2
  shift 2
  { echo "## $title"; echo; echo '```'
    "$@"; rc=$?
    echo '```'; echo; } >> "$file"
  [ "$rc" = 0 ] || { echo "bench.sh: $* failed" >&2; status=1; }
}

# Triangulation and convex parts per vertex at 100 to 10,000 vertices, beside earcut (node) and
# love.math.triangulate where installed (full run only: it takes about a minute).
concave=$sections/concave.md
if [ "$quick" != 1 ]; then
  for lua in luajit lua5.4; do
    command -v "$lua" >/dev/null 2>&1 || continue
    love=0; [ "$lua" = luajit ] && love=1
    section "$concave" "Concave shapes on $lua: \`LOVE=$love $lua bench/concave.lua\`" \
      env LOVE=$love "$lua" bench/concave.lua
  done
fi

# Outlines with holes against earcut: its fixtures, tile maps with 100+ holes, noisy outlines of
# 100 to 10,000 vertices, warm and first call, LuaJIT and Lua 5.4 side by side (bench/holes.lua;
# full run only: about a minute and a half).
holes=$sections/holes.md
if [ "$quick" != 1 ] && command -v luajit >/dev/null 2>&1; then
  section "$holes" "Outlines with holes against earcut: \`luajit bench/holes.lua\`" luajit bench/holes.lua
fi

# One input repeated against different inputs taken in turn, polygonTriangulate and earcut, per
# vertex (bench/cycled.lua), and small inputs against a bare ear clipper and earcut
# (bench/floor.lua; full run only: about a minute and 30 s).
cycled=$sections/cycled.md
if [ "$quick" != 1 ] && command -v luajit >/dev/null 2>&1; then
  section "$cycled" "One input repeated against inputs in turn: \`luajit bench/cycled.lua\`" \
    luajit bench/cycled.lua
  section "$cycled" "Small inputs against a bare ear clipper: \`luajit bench/floor.lua\`" \
    luajit bench/floor.lua
fi

# Lists of convex parts against the convex pair calls they need (bench/compound.lua), each ratio
# in 16 processes (full run only: about a minute on LuaJIT, two on Lua 5.4).
compound=$sections/compound.md
if [ "$quick" != 1 ]; then
  for lua in luajit lua5.4; do
    command -v "$lua" >/dev/null 2>&1 || continue
    calls=100000; [ "$lua" = luajit ] || calls=20000
    { echo "## Lists of convex parts on $lua: \`$lua bench/compound.lua draws 16 $calls\`"; echo
      "$lua" bench/compound.lua draws 16 "$calls"; rc=$?
      echo; } >> "$compound"
    [ "$rc" = 0 ] || { echo "bench.sh: $lua bench/compound.lua failed" >&2; status=1; }
  done
fi

{
  echo "# Benchmark: polygon.lua against the tutorial's formulas"
  echo
  echo "Made by \`make bench\` (\`bash bench/bench.sh\`) on$ran, polygon.lua of $rev."
  echo "Each row times polygon.lua and bench/baseline.lua, a plain transcription of the tutorial's"
  echo "formulas with their defects, in the same process on the same prepared inputs, in rounds that"
  echo "alternate the two (the ratio is taken per round; its median and interquartile range are shown),"
  echo "and counts their errors against exact answers (spec/support/oracle.lua, big-integer arithmetic)."
  echo "The ratio is polygon.lua's time over the baseline's: below 1 is faster. The targets hold for"
  echo "LuaJIT and Lua 5.4; Lua 5.2 and 5.1 are reported without targets. The validate row times"
  echo "polygon.lua against itself: its spread is the noise of the machine."
  echo
  echo "![time per call against error](speed-vs-error.png)"
  echo
  for lua in $ran; do [ -f "$sections/$lua.md" ] && cat "$sections/$lua.md"; done
  [ -f "$concave" ] && cat "$concave"
  [ -f "$holes" ] && cat "$holes"
  [ -f "$cycled" ] && cat "$cycled"
  [ -f "$compound" ] && cat "$compound"
} > "$out/RESULTS.md"
rm -rf "$sections"

if command -v gnuplot >/dev/null 2>&1; then
  gnuplot -e "out='$out/speed-vs-error.png'; jitdata='$out/data/luajit.dat'; pucdata='$out/data/lua5.4.dat'" \
    bench/plot.gp || { echo "bench.sh: gnuplot bench/plot.gp failed" >&2; status=1; }
else
  echo "bench.sh: gnuplot not installed, bench/speed-vs-error.png not made" >&2
fi
echo "bench.sh: wrote $out/RESULTS.md in $(( $(date +%s) - start )) s (status $status)" >&2
if [ "$quick" = 1 ]; then rm -rf "$out"; fi
exit $status
