#!/bin/bash
# bench/aborts.sh [RUNS] [PATTERN]: LuaJIT's aborted traces in the library (polygon.lua and polygon/) over RUNS runs of the
# quick benchmark (`luajit -jv`, every row, or those matching the --only PATTERN of bench/run.lua),
# from the repository root. Which traces form depends on the order in which loops and exits grow
# hot, which differs from run to run, so one run proves little. Prints, per kind of abort, how
# many there were and in how many runs, then the NYI ones (those that fail again on every retry)
# by file and line.
runs=${1:-10}
only=${2:-.}
log=$(mktemp)
tally=$(mktemp)
trap 'rm -f "$log" "$tally"' EXIT
# LuaJIT names a trace's chunk by its file name alone: the front's and each of polygon/'s
files="polygon$(for f in polygon/*.lua; do printf '|%s' "$(basename "$f" .lua)"; done)"
for run in $(seq "$runs"); do
  luajit -jv="$log" bench/run.lua --quick --only "$only" > /dev/null || exit 1
  grep -E -- "--- (\\([0-9/]+\\) )?($files)\\.lua:" "$log" | sed "s/^/$run /" >> "$tally"
done
echo "LuaJIT aborts in the library over $runs quick benchmark runs (only: $only)"
for kind in "NYI" "leaving loop in root trace" "inner loop in root trace" "loop unroll limit reached"; do
  printf '  %-30s %5d aborts, in %2d runs\n' "$kind" "$(grep -c -- "$kind" "$tally")" \
    "$(grep -- "$kind" "$tally" | cut -d' ' -f1 | sort -u | wc -l)"
done
echo "NYI aborts by file and line (count, file:line, reason):"
grep NYI "$tally" | sed -E 's/.*--- (\([0-9/]+\) )?([a-z]+\.lua:[0-9]+) -- (NYI: [a-z ]*).*/\2 \3/' | sort | uniq -c |
  sort -rn
