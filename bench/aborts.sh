#!/bin/bash
# bench/aborts.sh [RUNS] [PATTERN]: LuaJIT's aborted traces in polygon.lua over RUNS runs of the
# quick benchmark (`luajit -jv`, every row, or those matching the --only PATTERN of bench/run.lua),
# from the repository root. Which traces form depends on the order in which loops and exits grow
# hot, which differs from run to run, so one run proves little. Prints, per kind of abort, how
# many there were and in how many runs, then the NYI ones (those that fail again on every retry)
# by line of polygon.lua.
runs=${1:-10}
only=${2:-.}
log=$(mktemp)
tally=$(mktemp)
trap 'rm -f "$log" "$tally"' EXIT
for run in $(seq "$runs"); do
  luajit -jv="$log" bench/run.lua --quick --only "$only" > /dev/null || exit 1
  grep -- '--- .*polygon.lua' "$log" | sed "s/^/$run /" >> "$tally"
done
echo "LuaJIT aborts in polygon.lua over $runs quick benchmark runs (only: $only)"
for kind in "NYI" "leaving loop in root trace" "inner loop in root trace" "loop unroll limit reached"; do
  printf '  %-30s %5d aborts, in %2d runs\n' "$kind" "$(grep -c -- "$kind" "$tally")" \
    "$(grep -- "$kind" "$tally" | cut -d' ' -f1 | sort -u | wc -l)"
done
echo "NYI aborts by line of polygon.lua (count, line, reason):"
grep NYI "$tally" | sed 's/.*polygon.lua:\([0-9]*\) -- \(NYI: [a-z ]*\).*/\1 \2/' | sort | uniq -c |
  sort -rn
