#!/bin/sh
# bench/bench.sh: polygon.lua against the tutorial's formulas, speed beside error.
#
#   sh bench/bench.sh                 full run (about a minute on 2 cores): prints the tables and
#                                     writes bench/RESULTS.md, bench/data/<lua>.dat and, when
#                                     gnuplot is installed, bench/speed-vs-error.png
#   BENCH_QUICK=1 sh bench/bench.sh   a few seconds, small inputs, writes only to a temporary
#                                     directory (for CI: the benchmark must never silently break)
#   BENCH_LUAS="luajit" sh bench/bench.sh   choose the interpreters (default: luajit lua5.4 lua5.1)
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
  echo "Made by \`make bench\` (\`sh bench/bench.sh\`) on$ran. Each row times polygon.lua and"
  echo "bench/baseline.lua, a plain transcription of the tutorial's formulas with their defects, in"
  echo "the same process on the same prepared inputs, and counts their errors against exact answers"
  echo "(bench/exact.lua, floating-point expansions). The ratio is polygon.lua's time over the"
  echo "baseline's: below 1 is faster. Single-row ratios on LuaJIT move by about 5% from run to run"
  echo "(see \`--aa\` in bench/run.lua for the A/A test that measures this)."
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
