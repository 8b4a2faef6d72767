#!/bin/sh
# bench/bench.sh: polygon.lua against the tutorial's formulas, speed beside error.
#
#   bash bench/bench.sh               full run (about a minute on 2 cores): prints the tables and
#                                     writes bench/RESULTS.md, bench/data/<lua>.dat and, when
#                                     gnuplot is installed, bench/speed-vs-error.png
#   BENCH_QUICK=1 bash bench/bench.sh a few seconds, small inputs, writes only to a temporary
#                                     directory (for CI: the benchmark must never silently break)
#   BENCH_LUAS="luajit" bash bench/bench.sh   choose the interpreters (default: luajit lua5.4 lua5.1)
#
# Exits non-zero when a run fails: an error in a row, a function missing from polygon.lua, a NaN
# checksum, no interpreter found, or gnuplot failing on bench/plot.gp.
set -u
cd "$(dirname "$0")/.." || exit 2

quick=${BENCH_QUICK:-0}
luas=${BENCH_LUAS:-luajit lua5.4 lua5.1}
if [ "$quick" = 1 ]; then
  out=$(mktemp -d "${TMPDIR:-/tmp}/polygon-bench.XXXXXX") || exit 2
  flag=--quick
else
  out=bench
  flag=
fi
sections=$(mktemp -d "${TMPDIR:-/tmp}/polygon-bench-sections.XXXXXX") || exit 2
mkdir -p "$out/data"

# which polygon.lua was measured (BENCH_REV overrides, e.g. when run from an exported tree)
rev=${BENCH_REV:-$(git rev-parse --short HEAD 2>/dev/null || echo "an unknown revision")}
if git rev-parse --git-dir >/dev/null 2>&1 && ! git diff --quiet HEAD -- polygon.lua 2>/dev/null; then
  rev="$rev plus uncommitted changes to polygon.lua"
fi

status=0
ran=
start=$(date +%s)
for lua in $luas; do
  if ! command -v "$lua" >/dev/null 2>&1; then
    echo "bench.sh: $lua not found, skipped" >&2
    continue
  fi
  # shellcheck disable=SC2086
  if ! "$lua" bench/run.lua $flag --label "$lua" --out "$sections/$lua.md" --data "$out/data/$lua.dat"; then
    echo "bench.sh: $lua bench/run.lua failed" >&2
    status=1
  fi
  ran="$ran $lua"
done
if [ -z "$ran" ]; then
  echo "bench.sh: no Lua interpreter found (tried: $luas)" >&2
  exit 1
fi

{
  echo "# Benchmark: polygon.lua against the tutorial's formulas"
  echo
  echo "Made by \`make bench\` (\`bash bench/bench.sh\`) on$ran, polygon.lua of $rev."
  echo "Each row times polygon.lua and bench/baseline.lua, a plain transcription of the tutorial's"
  echo "formulas with their defects, in the same process on the same prepared inputs, and counts"
  echo "their errors against exact answers (bench/exact.lua, floating-point expansions). The ratio"
  echo "is polygon.lua's time over the baseline's: below 1 is faster. On LuaJIT a ratio moves from"
  echo "run to run: about 5% for most rows in an A/A test (\`luajit bench/run.lua --aa\`, the"
  echo "baseline against a copy of itself), more for branchy code (polygonsCollideV on the mixed"
  echo "pairs gave 0.32 to 0.41 over three runs of the same polygon.lua). PUC Lua varies by 2%."
  echo
  echo "![time per call against error](speed-vs-error.png)"
  echo
  for lua in $ran; do
    [ -f "$sections/$lua.md" ] && cat "$sections/$lua.md"
  done
} > "$out/RESULTS.md"
rm -rf "$sections"

if command -v gnuplot >/dev/null 2>&1; then
  if ! gnuplot -e "out='$out/speed-vs-error.png'; jitdata='$out/data/luajit.dat'; pucdata='$out/data/lua5.4.dat'" bench/plot.gp; then
    echo "bench.sh: gnuplot bench/plot.gp failed" >&2
    status=1
  fi
else
  echo "bench.sh: gnuplot not installed, bench/speed-vs-error.png not made" >&2
fi

echo "bench.sh: wrote $out/RESULTS.md in $(( $(date +%s) - start )) s (status $status)" >&2
if [ "$quick" = 1 ]; then rm -rf "$out"; fi
exit $status
