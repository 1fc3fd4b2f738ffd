#!/bin/bash
# Soak run of tyndall-viewer: a scripted session that orbits, switches the
# transmittance method, moves the light and changes the extinction (density
# scale) and the coefficient count, frame after frame, with a `report` line
# (resident memory, live OpenGL objects) every 100 frames. Prints the report
# lines and the growth between the first report after warm-up and the last.
#
#   Documentation/scripts/soak_viewer.sh [BUILD_DIR] [LOOPS] [SIZE]
#
# Defaults: ./build, 300 loops of 10 frames (3000 frames), 128 x 128 window,
# the built-in cloud at 64^3. Needs a display: run it under xvfb-run.
set -euo pipefail
build="${1:-build}"
loops="${2:-300}"
size="${3:-128}"
script="$(mktemp --suffix=.txt)"
trap 'rm -f "$script"' EXIT
{
  echo "hud off"
  echo "frames 20"
  echo "report"
  for ((i = 0; i < loops; ++i)); do
    echo "orbit 6 2"
    echo "key $((i % 6 + 1))"
    echo "light 12 -4"
    if ((i % 2)); then echo "key d"; else echo "key c"; fi
    if ((i % 3 == 0)); then echo "key plus"; elif ((i % 3 == 1)); then echo "key minus"; else echo "zoom 1.01"; fi
    echo "orbit -3 1"
    echo "frames 4"
    if ((i % 10 == 9)); then echo "report"; fi
  done
  echo "quit"
} > "$script"
start=$(date +%s)
"$build/bin/tyndall-viewer" -s "$size" "$size" -r 64 --script "$script" > "$script.out"
end=$(date +%s)
grep '^report' "$script.out"
frames=$(grep -c '^frame ' "$script.out" || true)
echo "soak: $frames frames in $((end - start)) s"
# Warm-up: until every method's shaders exist (the second report, after
# the first loops have visited all six methods).
grep '^report' "$script.out" | tail -n +2 | awk '
  NR == 1 { first = $5; objects = $6 " " $7 " " $8 " " $9 " " $10 " " $11 " " $12 " " $13 " " $14 " " $15 }
  { rss = $5; if (rss > max) max = rss; if (min == "" || rss < min) min = rss; last = $0 }
  END {
    split(last, l, " ")
    printf "after warm-up: rss %s MiB, %s\n", first, objects
    printf "last:          rss %s MiB, %s %s %s %s %s %s %s %s %s %s\n", l[5], l[6], l[7], l[8], l[9], l[10], l[11], l[12], l[13], l[14], l[15]
    printf "rss range after warm-up: %s .. %s MiB\n", min, max
  }'

rm -f "$script.out"
