#!/usr/bin/env bash
# Renders the seven LÖVE demo scenes headless (Xvfb, software OpenGL), each after its scripted
# drag, and checks that every PNG exists and is not blank (main.lua also refuses to write a
# picture with fewer than 8 colours or under 5% drawn).
#   bash examples/love/check-screenshots.sh          into a temporary folder, removed after
#   bash examples/love/check-screenshots.sh docs     into docs/ (the README's pictures)
set -u
cd "$(dirname "$0")/../.." || exit 1
if [ $# -ge 1 ]; then
  out=$1; mkdir -p "$out"
else
  out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
fi
out=$(cd "$out" && pwd)
rm -f "$out"/scene[1-7].png
if ! timeout 120 xvfb-run -a love examples/love --screenshots "$out"; then
  echo "love examples/love --screenshots failed" >&2
  exit 1
fi
status=0
for i in 1 2 3 4 5 6 7; do
  f="$out/scene$i.png"
  size=$(stat -c %s "$f" 2>/dev/null || echo 0)
  if [ "$size" -lt 10000 ]; then
    echo "scene $i: $f missing or too small ($size bytes)" >&2
    status=1
  fi
  # a PNG starts with \x89PNG
  if [ "$size" -gt 0 ] && [ "$(head -c 4 "$f" | tail -c 3)" != "PNG" ]; then
    echo "scene $i: $f is not a PNG" >&2
    status=1
  fi
done
[ "$status" -eq 0 ] && echo "seven scenes rendered into $out"
exit "$status"
